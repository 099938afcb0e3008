// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __model_core__: the value of a physically based model's channel, compiled:
// inst/models/__lafortune_model_core__.m's sum (rho_d / pi + sum_k ks_k g_k) with the lobe
// g of each type's definition (inst/models/private/brdf_TYPE.m) and the angles of
// brdf_geom.m, for the renderers' shading from a cached trace (the private
// model_value calls it when it is built).  The Octave code stays the
// reference: every operation is the one those files make, in their order,
// built with -ffp-contract=off (src/Makefile) and with std::fmin/fmax, which
// ignore a NaN as Octave's min and max do; powers are written as Octave
// computes them (x .^ 2 as x * x, x .^ 3 as x * x * x, other exponents by
// std::pow).  The tests compare it with the Octave code (test_core_engines);
// a change to one is made to the other in the same commit.  Rows are shared
// out over the machine's cores, each thread its own rows.

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

  enum Type { BLINNPHONG, WARD, COOKTORRANCE, GGX, ASHIKHMINSHIRLEY };

  // brdf_geom's angles of one row X = [cos ti, cos to, wi.wo]
  struct Geom
  {
    double ci, co, hh, ch, t2, cd, s5;
  };

  inline Geom
  geom (double ci, double co, double w)
  {
    Geom G;
    G.ci = ci;
    G.co = co;
    G.hh = std::fmax (2 + 2 * w, DBL_MIN);
    const double s = ci + co;
    G.ch = s / std::sqrt (G.hh);
    G.t2 = std::fmax (G.hh - s * s, 0) / (s * s);
    G.cd = std::fmin (std::sqrt (G.hh) / 2, 1);
    G.s5 = std::pow (1 - G.cd, 5.0);
    return G;
  }

  // the lobe of unit amplitude of type T with shape parameters Q at G
  inline double
  lobe (Type t, const double *q, const Geom& G)
  {
    switch (t)
      {
      case BLINNPHONG:
        {
          const double n = q[0];
          const double lc = std::log (G.ch);
          return (n + 2) / (2 * PI) * std::exp (n * lc);
        }
      case WARD:
        {
          const double a = q[0];
          const double s = G.ci + G.co;
          return G.hh / (PI * std::pow (a, 2.0) * std::pow (s, 4.0))
                 * std::exp (-G.t2 / std::pow (a, 2.0));
        }
      case COOKTORRANCE:
        {
          const double m = q[0], F0 = q[1];
          const double m2 = std::pow (m, 2.0);
          const double D = std::exp (-G.t2 / m2) / (m2 * std::pow (G.ch, 4.0));
          const double V = std::fmin (1, std::fmin (2 * G.ch * G.co / G.cd,
                                                    2 * G.ch * G.ci / G.cd));
          const double DG = D * V / (PI * G.ci * G.co);
          return DG * (F0 + (1 - F0) * G.s5);
        }
      case GGX:
        {
          const double a = q[0], F0 = q[1];
          const double a2 = std::pow (a, 2.0);
          const double den = a2 + G.t2;
          const double D = a2 / (PI * std::pow (G.ch, 4.0) * (den * den));
          const double ti2 = (1 - G.ci * G.ci) / (G.ci * G.ci);
          const double to2 = (1 - G.co * G.co) / (G.co * G.co);
          const double ri = std::sqrt (1 + a2 * ti2);
          const double ro = std::sqrt (1 + a2 * to2);
          const double V = 1 / (1 + (ri - 1) / 2 + (ro - 1) / 2);
          const double DV = D * V / (4 * G.ci * G.co);
          return DV * (F0 + (1 - F0) * G.s5);
        }
      case ASHIKHMINSHIRLEY:
        {
          const double n = q[0], F0 = q[1];
          const double lc = std::log (G.ch);
          const double A = (n + 1) / (8 * PI) * std::exp (n * lc)
                           / (G.cd * std::fmax (G.ci, G.co));
          return A * (F0 + (1 - F0) * G.s5);
        }
      }
    return 0;
  }

  bool
  type_of (const std::string& s, Type& t, int& nshape)
  {
    if (s == "blinnphong")        { t = BLINNPHONG; nshape = 1; }
    else if (s == "ward")         { t = WARD; nshape = 1; }
    else if (s == "cooktorrance") { t = COOKTORRANCE; nshape = 2; }
    else if (s == "ggx")          { t = GGX; nshape = 2; }
    else if (s == "ashikhminshirley") { t = ASHIKHMINSHIRLEY; nshape = 2; }
    else return false;
    return true;
  }
}

DEFUN_DLD (__model_core__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {@var{f} =} __model_core__ (@var{type}, @var{p}, @var{X})\n\
Internal: the compiled value of the private @code{model_core} (see there)\n\
for a physically based @var{type} (@qcode{\"blinnphong\"}, @qcode{\"ward\"},\n\
@qcode{\"cooktorrance\"}, @qcode{\"ggx\"}, @qcode{\"ashikhminshirley\"});\n\
@var{p} = [rho_d; ks_1; shape_1; ...] (real doubles, the layout of\n\
@code{model_pack}), @var{X} = [cos ti, cos to, wi.wo] (N x 3 real doubles,\n\
both cosines > 0).  @var{f} is N x 1.\n\
@end deftypefn")
{
  if (args.length () != 3)
    print_usage ();
  if (! args(0).is_string ())
    error_with_id ("lafortune:badInput", "__model_core__: TYPE must be a string, got %s",
                   args(0).class_name ().c_str ());
  const std::string ts = args(0).string_value ();
  Type t;
  int ns;
  if (! type_of (ts, t, ns))
    error_with_id ("lafortune:badInput",
                   "__model_core__: unknown TYPE '%s': expected blinnphong, ward, cooktorrance, ggx or ashikhminshirley",
                   ts.c_str ());
  const octave_value& pv = args(1);
  if (! pv.is_double_type () || pv.iscomplex () || pv.issparse () || pv.ndims () != 2
      || ! (pv.columns () == 1 || pv.rows () == 1))
    error_with_id ("lafortune:badInput", "__model_core__: P must be a real double vector, got %s",
                   what_of (pv).c_str ());
  const octave_idx_type np = pv.numel ();
  const int m = 1 + ns;
  if (np < 1 || (np - 1) % m != 0)
    error_with_id ("lafortune:badInput",
                   "__model_core__: P must have 1 + %d k elements for type %s (rho_d, then ks and %d shape parameters per lobe), got %ld",
                   m, ts.c_str (), ns, static_cast<long> (np));
  const octave_value& xv = args(2);
  if (! xv.is_double_type () || xv.iscomplex () || xv.issparse () || xv.ndims () != 2
      || xv.columns () != 3)
    error_with_id ("lafortune:badInput", "__model_core__: X must be a real double N x 3 array, got %s",
                   what_of (xv).c_str ());
  const NDArray p = pv.array_value ();
  const Matrix X = xv.matrix_value ();
  const octave_idx_type n = X.rows ();
  ColumnVector f;
  oct_guard ("__model_core__", [&] ()
  {
    f = ColumnVector (n, 0.0 + p(0) / PI);
    double *pf = f.fortran_vec ();
    const double *pp = p.data ();
    const double *x = X.data ();
    const octave_idx_type nl = (np - 1) / m;
    auto rows = [=] (octave_idx_type a, octave_idx_type b)
    {
      for (octave_idx_type k = 0; k < nl; k++)
        {
          const double ks = pp[1 + k * m];
          if (ks == 0)
            continue;
          const double *q = pp + 2 + k * m;
          for (octave_idx_type i = a; i < b; i++)
            {
              const Geom G = geom (x[i], x[n + i], x[2 * n + i]);
              pf[i] += ks * lobe (t, q, G);
            }
        }
    };
    oct_rows (n, rows);
  });
  return ovl (f);
}

/*
%!error <Invalid call> __model_core__ ("ggx", 1)
%!error <TYPE must be a string> __model_core__ (1, 1, zeros (0, 3))
%!error <unknown TYPE 'lafortune'> __model_core__ ("lafortune", 1, zeros (0, 3))
%!error <P must be a real double vector, got 1x1 single> __model_core__ ("ggx", single (1), zeros (0, 3))
%!error <P must be a real double vector, got 2x2 double> __model_core__ ("ggx", ones (2), zeros (0, 3))
%!error <P must have 1 \+ 3 k elements for type ggx> __model_core__ ("ggx", [1 2], zeros (0, 3))
%!error <P must have 1 \+ 2 k elements for type ward> __model_core__ ("ward", [1 2 3 4], zeros (0, 3))
%!error <X must be a real double N x 3 array, got 2x2 double> __model_core__ ("ggx", 1, ones (2))
%!error <X must be a real double N x 3 array, got 1x3 single> __model_core__ ("ggx", 1, single ([1 1 1]))
%!error <X must be a real double N x 3 array, got 1x3 complex double> __model_core__ ("ggx", 1, [1i 1 1])
%!error <X must be a real double N x 3 array, got 1x3 sparse double> __model_core__ ("ggx", 1, sparse ([1 1 1]))
%!test
%! ## the diffuse term alone, and no row
%! assert (__model_core__ ("ggx", pi, [0.5 0.5 0; 1 1 1]), [1; 1]);
%! assert (size (__model_core__ ("ward", [1 2 0.1], zeros (0, 3))), [0 1]);
%!test
%! ## GGX at normal incidence and view: D = 1 / (pi alpha^2), G2 = 1, F = F0
%! a = 0.3; F0 = 0.04;
%! f = __model_core__ ("ggx", [0; 1; a; F0], [1 1 1]);
%! assert (f, 1 / (pi * a ^ 2) * F0 / 4, 1e-15);
*/
