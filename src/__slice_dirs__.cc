// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __slice_dirs__: the local directions of angle triples,
// __lafortune_slice_dirs__ compiled: the POV-Ray tables of a material's fits
// take about ten million such pairs (scene_slice), and the held-out renders
// of measured data one per light sample (material_x).  The m-file stays the
// definition and the reference: it calls this through
// __lafortune_oct_call__, and the tests compare the two bit for bit.  Every
// operation is the one the Octave code makes, in its order (std::sin and
// std::cos are the C library's, as Octave's; max and min as Octave's, which
// take the other operand for NaN; x .^ 2 as x * x; sums along a row from
// 0; built with -ffp-contract=off, src/Makefile).

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <stdexcept>

namespace
{
  // Octave's max (x, y) and min (x, y) of doubles: NaN in x gives y
  inline double
  omax (double x, double y)
  {
    return std::isnan (y) ? x : (x >= y ? x : y);
  }

  inline double
  omin (double x, double y)
  {
    return std::isnan (y) ? x : (x <= y ? x : y);
  }

  bool
  real_double (const octave_value& v)
  {
    return v.is_double_type () && ! v.iscomplex () && ! v.issparse ();
  }
}

DEFUN_DLD (__slice_dirs__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {[@var{wi}, @var{wo}] =} __slice_dirs__ (@var{ti}, @var{to}, @var{cg})\n\
Internal: the compiled directions of __lafortune_slice_dirs__ (see there)\n\
for N angle pairs @var{ti}, @var{to} (real doubles, N each) and the\n\
cosines @var{cg} (one, or N).  @var{wi} and @var{wo} are N x 3.\n\
@end deftypefn")
{
  if (args.length () != 3)
    print_usage ();
  const octave_value& tv = args(0);
  const octave_value& uv = args(1);
  const octave_value& gv = args(2);
  if (! real_double (tv) || ! real_double (uv) || ! real_double (gv))
    error_with_id ("lafortune:badInput", "__slice_dirs__: TI, TO and CG must be real doubles, got %s, %s and %s",
                   what_of (tv).c_str (), what_of (uv).c_str (), what_of (gv).c_str ());
  const octave_idx_type n = tv.numel ();
  if (uv.numel () != n || (gv.numel () != 1 && gv.numel () != n))
    error_with_id ("lafortune:badInput",
                   "__slice_dirs__: TO must have as many entries as TI (%ld), and CG one or as many",
                   static_cast<long> (n));

  Matrix wi (n, 3), wo (n, 3);
  oct_guard ("__slice_dirs__", [&] ()
    {
      const NDArray ti = tv.array_value ();
      const NDArray to = uv.array_value ();
      const NDArray cg = gv.array_value ();
      const bool one = cg.numel () == 1;
      double *a = wi.fortran_vec ();
      double *b = wo.fortran_vec ();
      for (octave_idx_type i = 0; i < n; i++)
        {
          const double si = std::sin (ti(i));
          const double ci = std::cos (ti(i));
          const double so = std::sin (to(i));
          const double co = std::cos (to(i));
          const double s = si * so;
          double cphi = ((one ? cg(0) : cg(i)) - ci * co) / s;
          if (s <= 0)
            cphi = 1;
          cphi = omin (omax (cphi, -1), 1);
          const double sphi = std::sqrt (1 - cphi * cphi);
          double w[3] = {si * cphi, si * sphi, ci};
          double q = 0;
          for (int c = 0; c < 3; c++)
            q += w[c] * w[c];
          const double len = std::sqrt (q);
          for (int c = 0; c < 3; c++)
            a[i + c * n] = w[c] / len;
          b[i] = so;
          b[i + n] = 0;
          b[i + 2 * n] = co;
        }
    });
  return ovl (wi, wo);
}

/*
%!test
%! ## the Octave code's bits, with a cosine per pair and one for all
%! ## (test_core_engines compares __lafortune_slice_dirs__ without the
%! ## oct-file on more pairs)
%! ti = [0; 0.3; 1.2; pi/2; 1.6; 0.7; NaN];
%! to = [0.2; 0; 1.1; 0.5; 0.1; 0.7; 0.4];
%! cg = [0.9; 0.95; -0.2; 0.3; 0.99; 1; 0.5];
%! [wi, wo] = __slice_dirs__ (ti, to, cg);
%! si = sin (ti); ci = cos (ti); so = sin (to); co = cos (to);
%! s = si .* so; cphi = (cg - ci .* co) ./ s; cphi(s <= 0) = 1;
%! cphi = min (max (cphi, -1), 1); sphi = sqrt (1 - cphi .^ 2);
%! w = [si .* cphi, si .* sphi, ci]; w ./= sqrt (sum (w .^ 2, 2));
%! bits = @(x) typecast (x(:), "uint64");          # NaN too
%! assert (isequal (bits (wi), bits (w)));
%! assert (isequal (bits (wo), bits ([so, zeros(7, 1), co])));
%! [wi1, wo1] = __slice_dirs__ (ti, to, 0.5);
%! [wi2, wo2] = __slice_dirs__ (ti, to, 0.5 * ones (7, 1));
%! assert (isequal (bits (wi1), bits (wi2)) && isequal (bits (wo1), bits (wo2)));
%!error <Invalid call> __slice_dirs__ (1, 2)
%!error <must be real doubles> __slice_dirs__ (single (1), 1, 1)
%!error <as many entries> __slice_dirs__ ([1; 2], 1, 1)
%!error <as many entries> __slice_dirs__ ([1; 2], [1; 2], [1; 2; 3])
*/
