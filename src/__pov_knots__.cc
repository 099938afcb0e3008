// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __pov_knots__: the greedy refinement of one table in inst/pov/private/pov_knots.m
// (its subfunctions greedy_one and interval_err), compiled: pov_write_scene
// spends most of its time there, in a thousand small Octave calls per table.
// pov_knots.m stays the definition and the reference: it calls this when it
// is built, and the tests compare the two bit for bit.  Every operation is
// the one the Octave code makes, in its order (built with -ffp-contract=off,
// src/Makefile), and the maxima are Octave's max: NaN ignored, the first of
// equal values kept, column-major order.

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
  // interval_err (x, G, W, M, lo, hi) of pov_knots.m, 0-based: the largest
  // weighted error of linear interpolation between rows LO and HI over the
  // rows between them where M holds, and the row where it is
  void
  interval_err (const double *x, const double *G, const double *W, const bool *M,
                octave_idx_type n, octave_idx_type m, octave_idx_type lo,
                octave_idx_type hi, double& emax, octave_idx_type& amax)
  {
    emax = 0;
    amax = lo;
    if (hi - lo < 2)
      return;
    const octave_idx_type nr = hi - lo - 1;
    const double dx = x[hi] - x[lo];
    double best = std::numeric_limits<double>::quiet_NaN ();
    octave_idx_type bi = -1;
    for (octave_idx_type j = 0; j < m; j++)
      {
        const double glo = G[lo + j * n];
        const double ghi = G[hi + j * n];
        for (octave_idx_type q = 0; q < nr; q++)
          {
            const octave_idx_type i = lo + 1 + q;
            double v = 0;
            if (M[i + j * n])
              {
                const double t = (x[i] - x[lo]) / dx;
                const double lin = (1 - t) * glo + t * ghi;
                v = W[i + j * n] * std::fabs (G[i + j * n] - lin);
              }
            if (std::isnan (best))
              {
                if (! std::isnan (v))
                  {
                    best = v;
                    bi = q + j * nr;
                  }
              }
            else if (v > best)
              {
                best = v;
                bi = q + j * nr;
              }
          }
      }
    emax = best;
    amax = lo + 1 + (bi < 0 ? 0 : bi % nr);
  }

  // Octave's [v, j] = max (e): NaN ignored, the first of equal values
  std::size_t
  argmax (const std::vector<double>& e, double& v)
  {
    v = std::numeric_limits<double>::quiet_NaN ();
    std::size_t k = 0;
    for (std::size_t j = 0; j < e.size (); j++)
      if (std::isnan (v) ? ! std::isnan (e[j]) : e[j] > v)
        {
          v = e[j];
          k = j;
        }
    return k;
  }

  std::string
  not_real (const octave_value& v, const char *what)
  {
    if (! v.is_double_type () || v.iscomplex () || v.issparse ())
      return std::string (what) + " must be a real full double array, got "
             + (v.iscomplex () ? std::string ("complex ") : std::string ())
             + v.class_name ();
    return "";
  }
}

DEFUN_DLD (__pov_knots__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {@var{kn} =} __pov_knots__ (@var{x}, @var{G}, @var{W}, @var{M}, @var{tol}, @var{nmax}, @var{kn0})\n\
Internal: the greedy refinement of one table of @code{pov_knots}, compiled.\n\
@var{x} (n x 1), @var{G} and @var{W} (n x m double), @var{M} (n x m logical),\n\
@var{kn0} the first entries (ascending 1-based rows): the entries\n\
@var{kn} (a column) that pov_knots's Octave code chooses, bit for bit.\n\
@end deftypefn")
{
  if (args.length () != 7)
    print_usage ();
  for (int k : {0, 1, 2, 4, 5, 6})
    {
      const char *names[] = {"X", "G", "W", "M", "TOL", "NMAX", "KN0"};
      std::string bad = not_real (args(k), names[k]);
      if (! bad.empty ())
        error_with_id ("lafortune:badInput", "__pov_knots__: %s", bad.c_str ());
    }
  if (! args(3).islogical () || args(3).issparse ())
    error_with_id ("lafortune:badInput", "__pov_knots__: M must be a full logical array, got %s",
                   args(3).class_name ().c_str ());
  const NDArray x = args(0).array_value ();
  const NDArray G = args(1).array_value ();
  const NDArray W = args(2).array_value ();
  const boolNDArray M = args(3).bool_array_value ();
  const octave_idx_type n = G.dims ().ndims () == 2 ? G.rows () : -1;
  const octave_idx_type m = n >= 0 ? G.columns () : -1;
  if (n < 0 || x.numel () != n || W.dims () != G.dims () || M.dims () != G.dims ())
    error_with_id ("lafortune:badInput",
                   "__pov_knots__: G must be n x m, X have n elements, W and M G's size; got G %s, X %s, W %s, M %s",
                   G.dims ().str ().c_str (), x.dims ().str ().c_str (),
                   W.dims ().str ().c_str (), M.dims ().str ().c_str ());
  if (args(4).numel () != 1 || args(5).numel () != 1)
    error_with_id ("lafortune:badInput", "__pov_knots__: TOL and NMAX must be scalars");
  const double tol = args(4).double_value ();
  const double nmaxd = args(5).double_value ();
  if (! (nmaxd >= 0) || nmaxd != std::floor (nmaxd))
    error_with_id ("lafortune:badInput", "__pov_knots__: NMAX must be a count, got %g", nmaxd);
  const NDArray k0 = args(6).array_value ();
  std::vector<octave_idx_type> kn;
  for (octave_idx_type i = 0; i < k0.numel (); i++)
    {
      const double v = k0(i);
      if (! (v >= 1 && v <= n && v == std::floor (v)) || (i > 0 && ! (v > k0(i-1))))
        error_with_id ("lafortune:badInput",
                       "__pov_knots__: KN0 must be ascending row numbers from 1 to %ld",
                       static_cast<long> (n));
      kn.push_back (static_cast<octave_idx_type> (v) - 1);
    }

  octave_value_list out;
  oct_guard ("__pov_knots__", [&] ()
  {
    const double *xp = x.data ();
    const double *Gp = G.data ();
    const double *Wp = W.data ();
    const bool *Mp = M.data ();
    const std::size_t nmax = static_cast<std::size_t> (nmaxd);
    if (kn.size () >= 2)
      {
        std::vector<double> e (kn.size () - 1);
        std::vector<octave_idx_type> a (kn.size () - 1);
        for (std::size_t j = 0; j + 1 < kn.size (); j++)
          interval_err (xp, Gp, Wp, Mp, n, m, kn[j], kn[j+1], e[j], a[j]);
        while (kn.size () < nmax)
          {
            double emax;
            const std::size_t j = argmax (e, emax);
            if (! (emax > tol))
              break;
            const octave_idx_type p = a[j];
            double e1, e2;
            octave_idx_type a1, a2;
            interval_err (xp, Gp, Wp, Mp, n, m, kn[j], p, e1, a1);
            interval_err (xp, Gp, Wp, Mp, n, m, p, kn[j+1], e2, a2);
            kn.insert (kn.begin () + j + 1, p);
            e[j] = e1;
            e.insert (e.begin () + j + 1, e2);
            a[j] = a1;
            a.insert (a.begin () + j + 1, a2);
          }
      }
    ColumnVector r (kn.size ());
    for (std::size_t i = 0; i < kn.size (); i++)
      r(i) = static_cast<double> (kn[i] + 1);
    out(0) = r;
  });
  return out;
}

/*
%!error <Invalid call> __pov_knots__ (1)
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2), ones (4, 2), true (4, 2), 0, 8, single ([1 4]))
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2), ones (4, 2), ones (4, 2), 0, 8, [1 4])
%!error id=lafortune:badInput __pov_knots__ ((1:3)', ones (4, 2), ones (4, 2), true (4, 2), 0, 8, [1 4])
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2), ones (4, 3), true (4, 2), 0, 8, [1 4])
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2), ones (4, 2), true (4, 2), 0, 8, [1 5])
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2), ones (4, 2), true (4, 2), 0, 8, [3 2])
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2), ones (4, 2), true (4, 2), 0, -1, [1 4])
%!error id=lafortune:badInput __pov_knots__ ((1:4)', ones (4, 2, 2), ones (4, 2, 2), true (4, 2, 2), 0, 8, [1 4])
%!error id=lafortune:badInput __pov_knots__ ((1:4)', complex (ones (4, 2)), ones (4, 2), true (4, 2), 0, 8, [1 4])
%!test
%! ## a kink in the middle: the entry goes there
%! x = (0:10)'; G = abs (x - 4);
%! assert (__pov_knots__ (x, G, ones (11, 1), true (11, 1), 1e-9, 8, [1 11]), [1; 5; 11]);
%! ## no room, or nothing above tol: the first entries
%! assert (__pov_knots__ (x, G, ones (11, 1), true (11, 1), 1e-9, 2, [1; 11]), [1; 11]);
%! assert (__pov_knots__ (x, G, ones (11, 1), true (11, 1), 100, 8, [1; 11]), [1; 11]);
%! ## one entry, no rows, NaN
%! assert (__pov_knots__ (x, G, ones (11, 1), true (11, 1), 0, 8, 3), 3);
%! assert (size (__pov_knots__ (zeros (0, 1), zeros (0, 1), zeros (0, 1), true (0, 1), 0, 8, zeros (0, 1))), [0 1]);
%! G(3) = NaN;
%! assert (__pov_knots__ (x, G, ones (11, 1), true (11, 1), 1e-9, 8, [1 11]), [1; 5; 11]);   # as pov_knots.m
*/
