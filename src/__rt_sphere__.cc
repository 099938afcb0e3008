// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_sphere__: rt_intersect's hits of rays with a sphere, compiled: the
// measured render of the sphere scene traces 16 million camera rays and
// about as many shadow rays, each a dozen element-wise Octave operations.
// rt_intersect's "sphere" case stays the definition and the reference
// (also its engine "octave"): it calls this through __lafortune_oct_call__,
// and the tests compare the two bit for bit.  Every operation is the one
// the Octave code makes, in its order (built with -ffp-contract=off,
// src/Makefile): sums along a row from 0, as Octave's sum (so that a
// signed zero comes out the same), max (x, 0) as Octave's max, x .^ 2 as
// x * x.

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <stdexcept>

DEFUN_DLD (__rt_sphere__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {[@var{t}, @var{ok}] =} __rt_sphere__ (@var{O}, @var{D}, @var{c}, @var{r2}, @var{t0}, @var{tb})\n\
Internal: the compiled hits of rt_intersect's @qcode{\"sphere\"} case (see\n\
there): the rays @var{O} + t @var{D} (N x 3 real doubles) with the sphere\n\
of centre @var{c} (1 x 3) and squared radius @var{r2}, between @var{t0}\n\
and @var{tb} (N x 1).  @var{t} (N x 1) is the nearer root, or the farther\n\
one where the nearer is not beyond @var{t0}; @var{ok} (N x 1 logical)\n\
where the ray hits within (@var{t0}, @var{tb}).\n\
@end deftypefn")
{
  if (args.length () != 6)
    print_usage ();
  const octave_value& ov = args(0);
  const octave_value& dv = args(1);
  if (! ov.is_double_type () || ov.iscomplex () || ov.issparse () || ov.ndims () != 2
      || ov.columns () != 3 || ! dv.is_double_type () || dv.iscomplex () || dv.issparse ()
      || dv.ndims () != 2 || dv.columns () != 3 || dv.rows () != ov.rows ())
    error_with_id ("lafortune:badInput",
                   "__rt_sphere__: O and D must be real N x 3 doubles of the same size, got %s and %s",
                   what_of (ov).c_str (), what_of (dv).c_str ());
  const octave_idx_type n = ov.rows ();
  if (! args(2).is_double_type () || args(2).iscomplex () || args(2).numel () != 3)
    error_with_id ("lafortune:badInput", "__rt_sphere__: C must be 3 real doubles, got %s",
                   what_of (args(2)).c_str ());
  if (! args(3).is_real_scalar () || ! args(3).is_double_type ())
    error_with_id ("lafortune:badInput", "__rt_sphere__: R2 must be a real double scalar");
  for (int i : {4, 5})
    if (! args(i).is_double_type () || args(i).iscomplex () || args(i).numel () != n)
      error_with_id ("lafortune:badInput",
                     "__rt_sphere__: T0 and TB must be real doubles, one per ray, got %s",
                     what_of (args(i)).c_str ());

  ColumnVector t (n);
  boolNDArray ok (dim_vector (n, 1));
  oct_guard ("__rt_sphere__", [&] ()
    {
      const Matrix O = ov.matrix_value ();
      const Matrix D = dv.matrix_value ();
      const NDArray C = args(2).array_value ();
      const double r2 = args(3).double_value ();
      const NDArray t0 = args(4).array_value ();
      const NDArray tb = args(5).array_value ();
      const double *o = O.data ();
      const double *d = D.data ();
      const double c[3] = {C(0), C(1), C(2)};
      for (octave_idx_type i = 0; i < n; i++)
        {
          double oc[3];
          for (int k = 0; k < 3; k++)
            oc[k] = o[i + k * n] - c[k];                   // oc = o - c
          double b = 0, q = 0;
          for (int k = 0; k < 3; k++)
            {
              b += oc[k] * d[i + k * n];                   // sum (oc .* d, 2)
              q += oc[k] * oc[k];                          // sum (oc .^ 2, 2)
            }
          const double disc = b * b - (q - r2);
          const double sq = std::sqrt (disc >= 0 ? disc : 0.0);   // max (disc, 0)
          double ti = -b - sq;
          if (ti <= t0(i))
            ti = -b + sq;
          t(i) = ti;
          ok(i) = disc >= 0 && ti > t0(i) && ti < tb(i);
        }
    });
  return ovl (t, ok);
}

/*
%!test
%! ## the Octave arithmetic of rt_intersect's sphere case, bit for bit
%! rand ("state", 3);
%! n = 5000;
%! O = [randn(n, 3) * 3; 0 0 0; 2 0 0; -0 0 5];
%! D = randn (rows (O), 3); D ./= sqrt (sum (D .^ 2, 2));
%! D(end,:) = [0 0 -1];
%! c = [0.1 -0.2 0.3]; r2 = 1.7 ^ 2;
%! t0 = 1e-9 * ones (rows (O), 1); t0(1:7:end) = 2;
%! tb = Inf (rows (O), 1); tb(1:5:end) = 3;
%! [t, ok] = __rt_sphere__ (O, D, c, r2, t0, tb);
%! oc = O - c;
%! b = sum (oc .* D, 2);
%! disc = b .^ 2 - (sum (oc .^ 2, 2) - r2);
%! sq = sqrt (max (disc, 0));
%! te = -b - sq;
%! back = te <= t0;
%! te(back) = -b(back) + sq(back);
%! assert (isequal (t, te));
%! assert (isequal (ok, disc >= 0 & te > t0 & te < tb));
%! assert (islogical (ok) && any (ok) && ! all (ok));
%!error <Invalid call> __rt_sphere__ (1)
%!error <O and D must be> __rt_sphere__ (zeros (2, 3), zeros (3, 3), [0 0 0], 1, [0; 0], [1; 1])
%!error <C must be> __rt_sphere__ (zeros (2, 3), zeros (2, 3), [0 0], 1, [0; 0], [1; 1])
%!error <R2 must be> __rt_sphere__ (zeros (2, 3), zeros (2, 3), [0 0 0], [1 2], [0; 0], [1; 1])
%!error <T0 and TB must be> __rt_sphere__ (zeros (2, 3), zeros (2, 3), [0 0 0], 1, 0, [1; 1])
*/
