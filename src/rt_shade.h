// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// rt_render's shading from the slice table and its sums of a chunk's
// samples into the pixels, compiled: the one C++ copy of rt_render's
// private slice_rad (slice_lookup) and chunk_sums, shared by the oct-files
// __rt_slice__ and __rt_accum__ (one chunk each) and __rt_slice_sum__ (a
// whole render from the trace cache).  The Octave subfunctions are the
// definition: every operation is theirs, in their order and precision
// (single for the interpolation; built with -ffp-contract=off).

#ifndef LAFORTUNE_RT_SHADE_H
#define LAFORTUNE_RT_SHADE_H

#include <octave/oct.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

// the slice table RM as the oct-files take it: rows x 3 real singles
inline bool
rt_table_ok (const octave_value& v)
{
  return v.is_single_type () && ! v.iscomplex () && v.ndims () == 2 && v.columns () == 3;
}

// NH, the table's step from theta_h to the next psi, as an index step
// within its NR rows, or an exception
inline octave_idx_type
rt_table_step (double nhd, octave_idx_type nr)
{
  if (! (nhd >= 0 && nhd < nr && nhd == std::floor (nhd)))
    throw std::invalid_argument ("NH must be an integer between 0 and rows (RM)");
  return static_cast<octave_idx_type> (nhd);
}

// slice_rad for M lit samples: the table R (NR x 3 singles, column-major)
// interpolated at the entries K (1-based), K+1, K+NH, K+NH+1 with the
// weights A, B, in single precision, then as double times COSI; into OUT
// (M x 3, column-major)
inline void
rt_slice_rad (const float *R, octave_idx_type nr, octave_idx_type nh, const std::int32_t *k,
              const float *a, const float *b, const double *cosi, octave_idx_type m, double *out)
{
  for (octave_idx_type i = 0; i < m; i++)
    {
      const octave_idx_type k0 = static_cast<octave_idx_type> (k[i]) - 1;
      if (k0 < 0 || k0 + nh + 1 >= nr)
        throw std::invalid_argument ("K must index the table's entries (K + NH + 1 <= rows (RM))");
      const float ai = a[i];
      const float bi = b[i];
      // the weights as slice_lookup forms them: ((1 - a) .* (1 - b)), ...
      const float w00 = (1.0f - ai) * (1.0f - bi);
      const float w10 = ai * (1.0f - bi);
      const float w01 = (1.0f - ai) * bi;
      const float w11 = ai * bi;
      for (int c = 0; c < 3; c++)
        {
          const float *Rc = R + c * nr;
          float v = w00 * Rc[k0];
          v = v + w10 * Rc[k0 + 1];
          v = v + w01 * Rc[k0 + nh];
          v = v + w11 * Rc[k0 + nh + 1];
          out[i + c * m] = static_cast<double> (v) * cosi[i];
        }
    }
}

// chunk_sums's sums of one chunk: the samples K0+1 ... K0+M (sample k at
// pixel mod (k - 1, NPIX) + 1), the lit ones' indices in the chunk LITH
// (NL of them, 1..M) with radiance RAD (NL x 3, column-major), the misses
// MISS with the background BG when it is not black.  TOUCHED gets the
// pixels the samples reach (0-based, in the order of their first sample),
// S each one's sum (3 per pixel), from 0 in the order of the sample index
// (accumarray's; a lit sample before a miss of the same index)
inline void
rt_chunk_sums (std::uint64_t npix, std::uint64_t k0, const std::int32_t *hs, octave_idx_type nl,
               const double *r, const bool *miss, octave_idx_type m, const double bg[3],
               std::vector<std::uint64_t>& touched, std::vector<double>& s)
{
  const bool anybg = bg[0] != 0 || bg[1] != 0 || bg[2] != 0;
  std::vector<std::int64_t> j;     // >= 0: row of RAD; < 0: -(sample) - 1
  j.reserve (nl + (anybg ? m : 0));
  bool sorted = true;
  for (octave_idx_type i = 0; i < nl; i++)
    {
      const std::int32_t h = hs[i];
      if (h < 1 || h > m)
        throw std::invalid_argument ("LITH must hold sample indices 1..numel (MISS)");
      if (i > 0 && h < hs[i-1])
        sorted = false;
      j.push_back (i);
    }
  if (anybg)
    {
      auto key = [&] (std::int64_t x) -> std::int64_t
        { return x >= 0 ? static_cast<std::int64_t> (hs[x]) - 1 : -x - 1; };
      std::vector<std::int64_t> mi;
      for (octave_idx_type i = 0; i < m; i++)
        if (miss[i])
          mi.push_back (-static_cast<std::int64_t> (i) - 1);
      if (sorted)                  // a merge of two sorted lists
        {
          std::vector<std::int64_t> out;
          out.reserve (j.size () + mi.size ());
          std::size_t a = 0, b = 0;
          while (a < j.size () || b < mi.size ())
            if (b == mi.size () || (a < j.size () && key (j[a]) <= key (mi[b])))
              out.push_back (j[a++]);
            else
              out.push_back (mi[b++]);
          j.swap (out);
        }
      else
        {
          j.insert (j.end (), mi.begin (), mi.end ());
          std::stable_sort (j.begin (), j.end (),
                            [&] (std::int64_t x, std::int64_t y) { return key (x) < key (y); });
        }
    }
  // each pixel's sum from 0, in the order of the samples; the chunk's
  // pixels are the SPAN from k0's on (mod NPIX)
  const std::uint64_t span = std::min<std::uint64_t> (m, npix);
  const std::uint64_t p0 = k0 % npix;
  std::vector<octave_idx_type> slot (span, -1);
  touched.clear ();
  s.clear ();
  touched.reserve (span);
  s.reserve (3 * span);
  for (const std::int64_t x : j)
    {
      const std::uint64_t smp = x >= 0 ? static_cast<std::uint64_t> (hs[x]) - 1
                                       : static_cast<std::uint64_t> (-x - 1);
      const std::uint64_t p = (k0 + smp) % npix;
      const std::uint64_t o = (p + npix - p0) % npix;
      octave_idx_type q = slot[o];
      if (q < 0)
        {
          q = slot[o] = touched.size ();
          touched.push_back (p);
          s.insert (s.end (), {0.0, 0.0, 0.0});
        }
      for (int c = 0; c < 3; c++)
        s[3 * q + c] += x >= 0 ? r[x + c * nl] : bg[c];
    }
}

#endif
