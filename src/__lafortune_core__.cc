// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __lafortune_core__: inst/models/__lafortune_lafortune_core__.m's arithmetic, compiled
// (the fit spends a third of its time there).  lafortune_core.m stays the
// one evaluation of the model: it calls this when it is built, and its own
// Octave code is the reference, which the tests compare with this bit for
// bit.  Every operation is the one lafortune_core.m makes, in its order:
// built with -ffp-contract=off (src/Makefile), so that no multiply-add is
// fused, and with std::fmin/fmax, which ignore a NaN as Octave's min and max
// do.  Values without the Jacobian on many rows (a render's light samples)
// are shared out over the machine's cores, each thread its own rows (every
// row's arithmetic is the same, so the result is the same bit for bit);
// the fit's calls (a few thousand rows, with the Jacobian) stay on one.

#include <octave/oct.h>

#include "oct_guard.h"
#include "oct_rows.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace
{
  const double PI = 3.14159265358979323846;   // == Octave's pi
  const double LOGMAX = 300;
  const double LOGMIN = -700;

  // One lobe (Cxy, Cz, e) added to F (N values) and, with J (column-major,
  // N rows), its three columns C (0-based, the Cxy column) to C + 2.
  void
  add_lobe (double cxy, double cz, double e, const double *sxy, const double *sz,
            octave_idx_type n, double *f, double *J, octave_idx_type c)
  {
    double *jx = J ? J + c * n : nullptr;
    double *jz = J ? J + (c + 1) * n : nullptr;
    double *je = J ? J + (c + 2) * n : nullptr;
    for (octave_idx_type i = 0; i < n; i++)
      {
        const double b = cxy * sxy[i] + cz * sz[i];
        if (! (b > 0))
          continue;                     // J stays 0 there
        const double lb = std::log (std::fmax (b, DBL_MIN));
        if (e == 0)
          {
            f[i] += 1;
            if (J)
              je[i] = lb;
            continue;
          }
        const double t = e * lb;
        const double L = std::exp (std::fmax (std::fmin (t, LOGMAX), LOGMIN));
        f[i] += L;
        if (J)
          {
            // where the lobe is capped its slope is 0 (not e * exp (...) * 0,
            // which is NaN for an e that makes e * exp (300) overflow)
            const bool live = t <= LOGMAX;
            const double dLdb = live ? e * std::exp (std::fmax (std::fmin (t - lb, LOGMAX), LOGMIN)) : 0.0;
            jx[i] = dLdb * sxy[i];
            jz[i] = dLdb * sz[i];
            je[i] = L * lb * (live ? 1.0 : 0.0);
          }
      }
  }

  // "" when V is a real full double vector (a column when COLUMN), else
  // what it is instead
  std::string
  not_vector (const octave_value& v, bool column)
  {
    if (! v.is_double_type ())
      return v.class_name ();
    if (v.iscomplex ())
      return "complex double";
    if (v.issparse ())
      return "sparse double";
    const bool vec = v.ndims () == 2 && (v.columns () == 1 || v.isempty ()
                                         || (! column && v.rows () == 1));
    if (! vec)
      return v.dims ().str () + " double";
    return "";
  }
}

DEFUN_DLD (__lafortune_core__, args, nargout,
           "-*- texinfo -*-\n\
@deftypefn {} {[@var{f}, @var{J}] =} __lafortune_core__ (@var{p}, @var{sxy}, @var{sz})\n\
Internal: the compiled arithmetic of the private @code{lafortune_core}\n\
(see there); @var{p} = [rho_d; Cxy_1; Cz_1; e_1; ...] (1 + 3 k real\n\
doubles), @var{sxy} and @var{sz} real double columns of equal length.\n\
@var{f} is N x 1, @var{J} N x numel (@var{p}).\n\
@end deftypefn")
{
  if (args.length () != 3)
    print_usage ();
  for (int a = 0; a < 3; a++)
    {
      const std::string what = not_vector (args(a), a > 0);
      if (! what.empty ())
        error_with_id ("lafortune:badInput",
                       "__lafortune_core__: %s must be a real double %s, got %s",
                       a == 0 ? "P" : (a == 1 ? "SXY" : "SZ"),
                       a == 0 ? "vector" : "column", what.c_str ());
    }
  const octave_idx_type np = args(0).numel ();
  if (np < 1 || (np - 1) % 3 != 0)
    error_with_id ("lafortune:badInput",
                   "__lafortune_core__: P must have 1 + 3 k elements (rho_d, then Cxy, Cz, e per lobe), got %ld",
                   static_cast<long> (np));
  const octave_idx_type n = args(1).numel ();
  if (args(2).numel () != n)
    error_with_id ("lafortune:badInput",
                   "__lafortune_core__: SXY and SZ must have equal lengths, got %ld and %ld",
                   static_cast<long> (n), static_cast<long> (args(2).numel ()));
  const bool jac = nargout > 1;
  const NDArray p = args(0).array_value ();
  const NDArray sxy = args(1).array_value ();
  const NDArray sz = args(2).array_value ();
  ColumnVector f;
  Matrix J;
  oct_guard ("__lafortune_core__", [&] ()
  {
    f = ColumnVector (n, 0.0 + p(0) / PI);
    if (jac)
      {
        J = Matrix (n, np, 0.0);
        double *j1 = J.fortran_vec ();
        for (octave_idx_type i = 0; i < n; i++)
          j1[i] = 1 / PI;
      }
    double *pf = f.fortran_vec ();
    double *pJ = jac ? J.fortran_vec () : nullptr;
    const octave_idx_type nl = (np - 1) / 3;
    const double *pp = p.data ();
    const double *px = sxy.data ();
    const double *pz = sz.data ();
    if (jac)
      {
        for (octave_idx_type k = 0; k < nl; k++)
          add_lobe (pp[3 * k + 1], pp[3 * k + 2], pp[3 * k + 3], px, pz, n, pf, pJ, 3 * k + 1);
        return;
      }
    // rows [a, b) of every lobe
    auto rows = [=] (octave_idx_type a, octave_idx_type b)
    {
      for (octave_idx_type k = 0; k < nl; k++)
        add_lobe (pp[3 * k + 1], pp[3 * k + 2], pp[3 * k + 3], px + a, pz + a, b - a,
                  pf + a, nullptr, 0);
    };
    oct_rows (n, rows);
  });
  octave_value_list out;
  out(0) = f;
  if (jac)
    out(1) = J;
  return out;
}

/*
%!error <Invalid call> __lafortune_core__ (1, 2)
%!error <P must be a real double vector, got single> __lafortune_core__ (single (1), 0, 0)
%!error <SXY must be a real double column, got complex double> __lafortune_core__ (1, 1i, 0)
%!error <SZ must be a real double column, got 2x2 double> __lafortune_core__ (1, 0, ones (2))
%!error <SZ must be a real double column, got 1x2 double> __lafortune_core__ (1, [0; 1], [0 1])
%!error <SXY must be a real double column, got sparse double> __lafortune_core__ (1, sparse (1), 0)
%!error <P must be a real double vector, got cell> __lafortune_core__ ({1}, 0, 0)
%!error <P must be a real double vector, got 2x2 double> __lafortune_core__ (ones (2), 0, 0)
%!error <P must have 1 \+ 3 k elements> __lafortune_core__ ([1 2], 0, 0)
%!error <P must have 1 \+ 3 k elements> __lafortune_core__ ([], 0, 0)
%!error <SXY and SZ must have equal lengths> __lafortune_core__ (1, [0; 1], 0)
%!test
%! [f, J] = __lafortune_core__ ([pi; -1; 1; 2], [-0.5; 0.5], [0.5; 0.5]);
%! assert (f, [2; 1], eps);
%! assert (J(:,1), [1; 1] / pi);
%! assert (J(2,2:4), [0 0 0]);
%! assert (J(1,2:4), [-1 1 0], eps);
%!test
%! ## the Jacobian against central differences, two lobes, rows on and off
%! ## each lobe; the value matches the model's formula
%! x = [linspace(-0.9, 0.9, 41)', linspace(0.05, 0.95, 41)'];
%! p = [0.3; -1.2; 0.9; 6; 0.4; 1.1; 2.5];
%! [f, J] = __lafortune_core__ (p, x(:,1), x(:,2));
%! g = p(1) / pi + max (p(2) * x(:,1) + p(3) * x(:,2), 0) .^ p(4) ...
%!     + max (p(5) * x(:,1) + p(6) * x(:,2), 0) .^ p(7);
%! assert (f, g, 1e-13 * max (g));
%! h = 1e-6;
%! for k = 1:numel (p)
%!   dp = zeros (size (p)); dp(k) = h;
%!   fd = (__lafortune_core__ (p + dp, x(:,1), x(:,2)) - __lafortune_core__ (p - dp, x(:,1), x(:,2))) / (2 * h);
%!   assert (J(:,k), fd, 1e-6 * max (abs (fd)) + 1e-9);
%! endfor
%!test
%! ## stiff and extreme lobes stay finite: a cap at exp(300), a tiny base,
%! ## e = 0 (the lobe is 1 where its base is positive), no lobe, no rows
%! [f, J] = __lafortune_core__ ([0; -1; 1; 1e7; 0; 1; 0], [-1; 0.5], [1; 0.5]);
%! assert (all (isfinite ([f(:); J(:)])));
%! assert (f, [exp(300) + 1; 1]);
%! assert (J(1,2:4), [0 0 0]);      # capped: no slope
%! assert (J(:,7), [0; log(0.5)], eps);
%! [f, J] = __lafortune_core__ ([0; -1; 1; 50], [-1e-300; 0], [1e-300; 0]);
%! assert (abs ([f; J(:,2:4)(:)]) < 1e-300);      # no denormals: cut at exp(-700)
%! [f, J] = __lafortune_core__ (2, [0.1; 0.2], [0.3; 0.4]);
%! assert (f, 2 / pi * [1; 1]);
%! assert (size (J), [2 1]);
%! [f, J] = __lafortune_core__ ([1; -1; 1; 2], zeros (0, 1), zeros (0, 1));
%! assert (size (f), [0 1]);
%! assert (size (J), [0 4]);
*/
