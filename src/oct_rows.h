// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// oct_rows (N, ROWS): call ROWS (a, b) on ranges [a, b) that cover the rows
// 0 to N - 1, shared out over the machine's cores (at most 8 threads, a
// thread for every 65536 rows at least), each thread its own rows; when no
// more threads can be started, the ranges not started are done here.  For
// the compiled cores whose rows are independent (every row's arithmetic is
// the same whichever thread does it, so the result is the same bit for bit):
// __lafortune_core__, __model_core__.  Call it inside oct_guard.

#ifndef LAFORTUNE_OCT_ROWS_H
#define LAFORTUNE_OCT_ROWS_H

#include <octave/oct.h>

#include <algorithm>
#include <thread>
#include <vector>

template <typename F>
void
oct_rows (octave_idx_type n, F rows)
{
  const octave_idx_type per = 65536;         // rows worth a thread
  unsigned nt = std::max (1u, std::min (std::thread::hardware_concurrency (), 8u));
  nt = static_cast<unsigned> (std::min<octave_idx_type> (nt, std::max<octave_idx_type> (1, n / per)));
  std::vector<octave_idx_type> cut (nt + 1);
  for (unsigned t = 0; t <= nt; t++)
    cut[t] = n * t / nt;
  std::vector<std::thread> pool;
  unsigned started = 1;                      // range 0 is this thread's
  try
    {
      for (unsigned t = 1; t < nt; t++, started++)
        pool.emplace_back (rows, cut[t], cut[t + 1]);
    }
  catch (...)
    {
      // no more threads: the ranges not started are done here
    }
  rows (cut[0], cut[1]);
  for (unsigned t = started; t < nt; t++)
    rows (cut[t], cut[t + 1]);
  for (auto& th : pool)
    th.join ();
}

#endif
