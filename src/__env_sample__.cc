// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __env_sample__: the sampling of an environment light by its luminance in
// inst/render/private/env_sample.m (and env_dirs's directions), compiled:
// the held-out renders draw a million light samples or more per light, each
// a dozen element-wise Octave operations.  env_sample.m stays the definition
// and the reference: it calls this through __lafortune_oct_call__, and the tests compare
// the two bit for bit.  Every operation is the one the Octave code makes, in
// its order (built with -ffp-contract=off, src/Makefile); Octave's lookup is
// the count of table entries <= the value (std::upper_bound), made within
// the drawn row.  The map's
// rotation (a 3 x 3 product, BLAS's) stays in Octave.

#include <octave/oct.h>

#include "oct_guard.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace
{
  inline double
  clamp01 (double f)
  {
    // Octave's min (max (f, 0), 1): NaN gives 0
    if (std::isnan (f))
      return 0;
    return std::min (std::max (f, 0.0), 1.0);
  }

  // Octave's lookup (T, y) on an increasing table of N entries
  inline double
  lookup (const double *T, octave_idx_type N, double y)
  {
    return static_cast<double> (std::upper_bound (T, T + N, y) - T);
  }
}

DEFUN_DLD (__env_sample__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {[@var{Lm}, @var{wt}] =} __env_sample__ (@var{cdf_row}, @var{cdf_col}, @var{p}, @var{rad}, @var{u}, @var{v})\n\
Internal: env_sample's draws, compiled.  @var{cdf_row} ((H+1) x 1),\n\
@var{cdf_col} (H (W+1) x 1), @var{p} (H x W) and @var{rad} (H W x 3) as\n\
env_dist makes them, @var{u} and @var{v} (N x 1, in [0, 1]): the\n\
directions @var{Lm} in the map's own frame (before its rotation) and the\n\
weights @var{wt} (N x 3) that env_sample's Octave code computes, bit for\n\
bit.\n\
@end deftypefn")
{
  if (args.length () != 6)
    print_usage ();
  const char *names[] = {"CDF_ROW", "CDF_COL", "P", "RAD", "U", "V"};
  for (int k = 0; k < 6; k++)
    if (! args(k).is_double_type () || args(k).iscomplex () || args(k).issparse ()
        || args(k).ndims () != 2)
      error_with_id ("lafortune:badInput", "__env_sample__: %s must be a real full double matrix, got %s",
                     names[k], what_of (args(k)).c_str ());
  const Matrix P = args(2).matrix_value ();
  const octave_idx_type H = P.rows ();
  const octave_idx_type W = P.columns ();
  const Matrix cr = args(0).matrix_value ();
  const Matrix cc = args(1).matrix_value ();
  const Matrix rad = args(3).matrix_value ();
  const Matrix u = args(4).matrix_value ();
  const Matrix v = args(5).matrix_value ();
  if (H < 1 || W < 1 || cr.numel () != H + 1 || cc.numel () != H * (W + 1)
      || rad.rows () != H * W || rad.columns () != 3)
    error_with_id ("lafortune:badInput",
                   "__env_sample__: P must be H x W with H, W >= 1, CDF_ROW have H+1 elements, CDF_COL H (W+1) and RAD be H W x 3; got P %s, CDF_ROW %s, CDF_COL %s, RAD %s",
                   P.dims ().str ().c_str (), cr.dims ().str ().c_str (), cc.dims ().str ().c_str (),
                   rad.dims ().str ().c_str ());
  if (u.numel () != v.numel ())
    error_with_id ("lafortune:badInput", "__env_sample__: U and V must have as many elements, got %s and %s",
                   u.dims ().str ().c_str (), v.dims ().str ().c_str ());

  octave_value_list out;
  oct_guard ("__env_sample__", [&] ()
  {
    const octave_idx_type N = u.numel ();
    Matrix Lm (N, 3), wt (N, 3);
    const double *C = cc.data ();
    const double *R = cr.data ();
    const double *p = P.data ();
    const double *rd = rad.data ();
    const octave_idx_type HW = H * W;
    const double Hd = static_cast<double> (H);
    const double Wd = static_cast<double> (W);
    const double W1 = Wd + 1;
    const double one_m_eps = 1 - std::numeric_limits<double>::epsilon ();
    const double tiny = std::numeric_limits<double>::min ();
    const double gc = (M_PI / Hd) * (2 * M_PI / Wd);
    for (octave_idx_type i = 0; i < N; i++)
      {
        // Octave's min (max (u, 0), 1 - eps): NaN gives 0
        double ui = u(i), vi = v(i);
        ui = std::isnan (ui) ? 0 : std::min (std::max (ui, 0.0), one_m_eps);
        vi = std::isnan (vi) ? 0 : std::min (std::max (vi, 0.0), one_m_eps);
        double r = lookup (R, H + 1, ui);
        r = std::min (std::max (r, 1.0), Hd);
        const octave_idx_type ri = static_cast<octave_idx_type> (r) - 1;
        const double fu = (ui - R[ri]) / std::max (R[ri + 1] - R[ri], tiny);
        const double x = (r - 1) + vi;
        // the count of CDF_COL's entries <= x: those of the rows before r
        // are all <= r - 1 <= x, those after it >= r, and x < r but where
        // (r - 1) + v rounds up to r, which the clamp below makes the same;
        // so the search is made in row r alone
        double j = (r - 1) * W1 + lookup (C + ri * (W + 1), W + 1, x);
        j = std::min (std::max (j, (r - 1) * W1 + 1), r * W1 - 1);
        const double c = j - (r - 1) * W1;
        const octave_idx_type ji = static_cast<octave_idx_type> (j) - 1;
        const double fv = (x - C[ji]) / std::max (C[ji + 1] - C[ji], tiny);
        const double th = (r - 1 + clamp01 (fu)) / Hd * M_PI;
        const double ph = (c - 1 + clamp01 (fv)) / Wd * 2 * M_PI - M_PI;
        const double st = std::sin (th);
        Lm(i, 0) = st * std::sin (ph);
        Lm(i, 1) = std::cos (th);
        Lm(i, 2) = -st * std::cos (ph);
        const octave_idx_type k = static_cast<octave_idx_type> (r + (c - 1) * Hd) - 1;
        if (k < 0 || k >= HW)
          throw std::runtime_error ("a texel outside the map (CDF_COL is not env_dist's)");
        const double g = gc * st / std::max (p[k], tiny);
        for (int q = 0; q < 3; q++)
          wt(i, q) = rd[k + q * HW] * g;
      }
    out(0) = Lm;
    out(1) = wt;
  });
  return out;
}

/*
%!error <Invalid call> __env_sample__ (1)
%!error id=lafortune:badInput __env_sample__ ([0; 1], [0; 0.5; 1], 1, [1 1 1], single (0.5), 0.5)
%!error id=lafortune:badInput __env_sample__ ([0; 1], [0; 0.5; 1], 1, [1 1 1], complex (0.5), 0.5)
%!error id=lafortune:badInput __env_sample__ ([0; 1], [0; 0.5; 1], 1, [1 1], 0.5, 0.5)
%!error id=lafortune:badInput __env_sample__ ([0; 1; 2], [0; 0.5; 1], 1, [1 1 1], 0.5, 0.5)
%!error id=lafortune:badInput __env_sample__ ([0; 1], [0; 0.5; 1], 1, [1 1 1], [0.5 0.5], 0.5)
%!test
%! ## one texel (H = W = 1): every draw is its centre's row, the whole sphere
%! [Lm, wt] = __env_sample__ ([0; 1], [0; 1], 1, [2 3 4], [0; 0.5; 1], [0.25; 0.5; 1]);
%! assert (size (Lm), [3 3]);
%! assert (sqrt (sum (Lm .^ 2, 2)), ones (3, 1), 1e-15);
%! assert (Lm(2,2), cos (pi / 2), eps);
%! assert (wt(2,:), [2 3 4] * 2 * pi ^ 2, 1e-12);
%! ## no draws
%! [Lm, wt] = __env_sample__ ([0; 1], [0; 1], 1, [2 3 4], zeros (0, 1), zeros (0, 1));
%! assert (size (Lm), [0 3]);
%! assert (size (wt), [0 3]);
*/
