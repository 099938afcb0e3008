// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __pov_knots_batch__: the vectorised refinement of many tables at once in
// inst/pov/private/pov_knots.m (its subfunction refine_batch), compiled:
// each pass there makes several n x m x B temporaries, and pov_write_scene
// runs it for every term of every fit.  pov_knots.m stays the definition and
// the reference: it calls this through __lafortune_oct_call__ when it is
// built (as __pov_knots__ for one table), and the tests compare the two bit
// for bit.  Every operation is the one the Octave code makes, in its
// order (built with -ffp-contract=off, src/Makefile); the maxima are
// Octave's max (NaN ignored, NaN when all are NaN), and the tables over
// their room keep their worst intervals as Octave's stable sort does.

#include <octave/oct.h>

#include "oct_guard.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace
{
  const double NaN = std::numeric_limits<double>::quiet_NaN ();

  // Octave's max (a, b) of two values, NaN ignored
  inline double
  nanmax (double a, double b)
  {
    if (std::isnan (a))
      return b;
    if (std::isnan (b))
      return a;
    return b > a ? b : a;
  }

  // K (n x B, true at the entries) refined as refine_batch does
  void
  refine (const double *x, const double *G, const double *W, std::vector<bool>& M,
          octave_idx_type n, octave_idx_type m, octave_idx_type B, double tol,
          double nmax, std::vector<bool>& K)
  {
    const octave_idx_type nB = n * B;
    std::vector<octave_idx_type> prev (nB), nxt (nB);
    std::vector<double> E (nB), emax (nB), bar (B), room (B);
    std::vector<octave_idx_type> sel;
    while (true)
      {
        for (octave_idx_type b = 0; b < B; b++)
          {
            const octave_idx_type c = b * n;
            // the entry at or before each row (row 1 when none), and at or
            // after it (row n when none); 0-based here
            octave_idx_type p = 0;
            for (octave_idx_type i = 0; i < n; i++)
              {
                if (K[c + i])
                  p = i;
                prev[c + i] = p;
              }
            octave_idx_type q = n - 1;
            for (octave_idx_type i = n - 1; i >= 0; i--)
              {
                if (K[c + i])
                  q = i;
                nxt[c + i] = q;
              }
            // the weighted error of linear interpolation, its maximum over
            // the columns, 0 at the entries and where M is false
            double colmax = NaN;
            for (octave_idx_type i = 0; i < n; i++)
              {
                const octave_idx_type pi = prev[c + i];
                const octave_idx_type ni = nxt[c + i];
                const double t = (x[i] - x[pi]) / std::max (x[ni] - x[pi],
                                                             std::numeric_limits<double>::min ());
                double e = NaN;
                for (octave_idx_type j = 0; j < m; j++)
                  {
                    const octave_idx_type o = j * n + b * n * m;
                    double v = 0;
                    if (M[o + i])
                      {
                        const double lin = (1 - t) * G[o + pi] + t * G[o + ni];
                        v = W[o + i] * std::fabs (G[o + i] - lin);
                      }
                    e = nanmax (e, v);
                  }
                if (K[c + i])
                  e = 0;
                E[c + i] = e;
                colmax = nanmax (colmax, e);
              }
            bar[b] = nanmax (tol, 0.5 * colmax);
            // each interval's largest error (NaN ignored)
            for (octave_idx_type i = 0; i < n; i++)
              emax[c + i] = NaN;
            for (octave_idx_type i = 0; i < n; i++)
              emax[c + prev[c + i]] = nanmax (emax[c + prev[c + i]], E[c + i]);
          }
        // per interval, its first row with an error above TOL, within a
        // factor 2 of its table's worst and the interval's largest
        sel.clear ();
        octave_idx_type last_key = -1;
        for (octave_idx_type k = 0; k < nB; k++)
          {
            const octave_idx_type b = k / n;
            const octave_idx_type key = prev[k] + b * n;
            const double e = E[k];
            if (e > tol && e >= bar[b] && e >= emax[key] && key != last_key)
              {
                sel.push_back (k);
                last_key = key;
              }
          }
        if (sel.empty ())
          break;
        // the tables with fewer free entries than splits keep their worst
        for (octave_idx_type b = 0; b < B; b++)
          {
            double used = 0;
            for (octave_idx_type i = 0; i < n; i++)
              used += K[b * n + i];
            room[b] = nmax - used;
          }
        std::vector<bool> drop (sel.size (), false);
        std::size_t s0 = 0;
        while (s0 < sel.size ())
          {
            const octave_idx_type b = sel[s0] / n;
            std::size_t s1 = s0;
            while (s1 < sel.size () && sel[s1] / n == b)
              s1++;
            const double cnt = static_cast<double> (s1 - s0);
            if (cnt > room[b])
              {
                std::vector<std::size_t> o (s1 - s0);
                std::iota (o.begin (), o.end (), s0);
                std::stable_sort (o.begin (), o.end (), [&] (std::size_t u, std::size_t v)
                                  { return E[sel[u]] > E[sel[v]]; });
                const double keep = std::max (room[b], 0.0);
                for (std::size_t r = 0; r < o.size (); r++)
                  if (static_cast<double> (r) >= keep)
                    drop[o[r]] = true;
              }
            s0 = s1;
          }
        bool any = false;
        for (std::size_t s = 0; s < sel.size (); s++)
          if (! drop[s])
            {
              K[sel[s]] = true;
              any = true;
            }
        if (! any)
          break;
      }
  }
}

DEFUN_DLD (__pov_knots_batch__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {@var{K} =} __pov_knots_batch__ (@var{x}, @var{G}, @var{W}, @var{M}, @var{tol}, @var{nmax}, @var{first}, @var{last}, @var{K0})\n\
Internal: the refinement of many tables at once of @code{pov_knots}, compiled.\n\
@var{x} (n x 1), @var{G} and @var{W} (n x m x B double), @var{M} (n x m x B\n\
logical), @var{first} and @var{last} (1 x B rows, 1-based), @var{K0} (n x B\n\
logical, the first entries): the entries @var{K} (n x B logical) that\n\
pov_knots's Octave code chooses, bit for bit.\n\
@end deftypefn")
{
  if (args.length () != 9)
    print_usage ();
  const char *names[] = {"X", "G", "W", "M", "TOL", "NMAX", "FIRST", "LAST", "K0"};
  for (int k : {0, 1, 2, 4, 5, 6, 7})
    if (! args(k).is_double_type () || args(k).iscomplex () || args(k).issparse ())
      error_with_id ("lafortune:badInput", "__pov_knots_batch__: %s must be a real full double array, got %s",
                     names[k], what_of (args(k)).c_str ());
  for (int k : {3, 8})
    if (! args(k).islogical () || args(k).issparse ())
      error_with_id ("lafortune:badInput", "__pov_knots_batch__: %s must be a full logical array, got %s",
                     names[k], what_of (args(k)).c_str ());
  const NDArray x = args(0).array_value ();
  const NDArray G = args(1).array_value ();
  const NDArray W = args(2).array_value ();
  const boolNDArray M0 = args(3).bool_array_value ();
  const dim_vector d = G.dims ();
  if (d.ndims () > 3)
    error_with_id ("lafortune:badInput", "__pov_knots_batch__: G must be n x m x B, got %s",
                   d.str ().c_str ());
  const octave_idx_type n = d(0);
  const octave_idx_type m = d(1);
  const octave_idx_type B = d.ndims () == 3 ? d(2) : 1;
  if (x.numel () != n || W.dims () != d || M0.dims () != d)
    error_with_id ("lafortune:badInput",
                   "__pov_knots_batch__: X must have n elements, W and M G's size; got G %s, X %s, W %s, M %s",
                   d.str ().c_str (), x.dims ().str ().c_str (), W.dims ().str ().c_str (),
                   M0.dims ().str ().c_str ());
  if (args(4).numel () != 1 || args(5).numel () != 1)
    error_with_id ("lafortune:badInput", "__pov_knots_batch__: TOL and NMAX must be scalars");
  const double tol = args(4).double_value ();
  const double nmax = args(5).double_value ();
  const NDArray first = args(6).array_value ();
  const NDArray last = args(7).array_value ();
  const boolNDArray K0 = args(8).bool_array_value ();
  if (first.numel () != B || last.numel () != B || K0.rows () != n || K0.numel () != n * B)
    error_with_id ("lafortune:badInput",
                   "__pov_knots_batch__: FIRST and LAST must have B = %ld elements and K0 be n x B; got %s, %s, %s",
                   static_cast<long> (B), first.dims ().str ().c_str (), last.dims ().str ().c_str (),
                   K0.dims ().str ().c_str ());
  for (octave_idx_type b = 0; b < B; b++)
    if (! (first(b) >= 1 && last(b) <= n && first(b) <= last(b)))
      error_with_id ("lafortune:badInput",
                     "__pov_knots_batch__: FIRST and LAST must be rows with 1 <= FIRST <= LAST <= %ld",
                     static_cast<long> (n));

  octave_value_list out;
  oct_guard ("__pov_knots_batch__", [&] ()
  {
    // the rows of each table from FIRST to LAST: where the error counts
    std::vector<bool> M (n * m * B);
    for (octave_idx_type b = 0; b < B; b++)
      for (octave_idx_type j = 0; j < m; j++)
        for (octave_idx_type i = 0; i < n; i++)
          {
            const octave_idx_type o = i + j * n + b * n * m;
            M[o] = M0(o) && (i + 1) >= first(b) && (i + 1) <= last(b);
          }
    std::vector<bool> K (n * B);
    for (octave_idx_type k = 0; k < n * B; k++)
      K[k] = K0(k);
    refine (x.data (), G.data (), W.data (), M, n, m, B, tol, nmax, K);
    boolNDArray r (dim_vector (n, B));
    for (octave_idx_type k = 0; k < n * B; k++)
      r(k) = K[k];
    out(0) = r;
  });
  return out;
}

/*
%!error <Invalid call> __pov_knots_batch__ (1)
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 1], [4 4], single (true (4, 2)))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2), ones (4, 2, 2), ones (4, 2, 2), 0, 8, [1 1], [4 4], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:3)', ones (4, 2, 2), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 1], [4 4], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2), ones (4, 3, 2), true (4, 2, 2), 0, 8, [1 1], [4 4], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 1 1], [4 4 4], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 3], [4 2], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 1], [4 5], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', complex (ones (4, 2, 2)), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 1], [4 4], true (4, 2))
%!error id=lafortune:badInput __pov_knots_batch__ ((1:4)', ones (4, 2, 2, 2), ones (4, 2, 2, 2), true (4, 2, 2, 2), 0, 8, [1 1], [4 4], true (4, 2))
%!test
%! ## two tables, each with a kink: the entry goes to each one's kink
%! x = (0:10)';
%! G = cat (3, abs (x - 4), abs (x - 7));
%! K0 = false (11, 2); K0([1 11],:) = true;
%! K = __pov_knots_batch__ (x, G, ones (11, 1, 2), true (11, 1, 2), 1e-9, 8, [1 1], [11 11], K0);
%! assert (find (K(:,1))', [1 5 11]);
%! assert (find (K(:,2))', [1 8 11]);
%! ## no room, or nothing above tol: the first entries
%! assert (__pov_knots_batch__ (x, G, ones (11, 1, 2), true (11, 1, 2), 1e-9, 2, [1 1], [11 11], K0), K0);
%! assert (__pov_knots_batch__ (x, G, ones (11, 1, 2), true (11, 1, 2), 100, 8, [1 1], [11 11], K0), K0);
*/
