// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_slice__: rt_render's shading of lit samples from the slice table
// (its subfunction slice_rad: the table interpolated bilinearly with the
// samples' weights, slice_lookup, in single precision, then times cos ti in
// double), compiled (rt_shade.h's rt_slice_rad).  A render from the trace cache in slice mode spends
// about half its time there.  slice_rad stays the definition and the
// reference: it calls this when it is built, and the tests compare the two
// bit for bit.  Every operation is the one the Octave code makes, in its
// order and precision (single for the interpolation, as Octave's single
// arithmetic; built with -ffp-contract=off, src/Makefile).

#include <octave/oct.h>

#include "oct_guard.h"
#include "rt_shade.h"

#include <cstdint>
#include <stdexcept>
#include <string>

DEFUN_DLD (__rt_slice__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {@var{rad} =} __rt_slice__ (@var{Rm}, @var{a}, @var{b}, @var{k}, @var{nh}, @var{cosi})\n\
Internal: the compiled radiance of rt_render's private @code{slice_rad} (see\n\
there): the slice table @var{Rm} (single, rows x 3) interpolated with the\n\
weights @var{a}, @var{b} (single) at the entries @var{k} (int32, 1-based),\n\
@var{k}+1, @var{k}+@var{nh}, @var{k}+@var{nh}+1, in single precision, then\n\
as double times @var{cosi} (double).  @var{rad} is numel (@var{k}) x 3.\n\
@end deftypefn")
{
  if (args.length () != 6)
    print_usage ();
  const octave_value& Rv = args(0);
  if (! rt_table_ok (Rv))
    error_with_id ("lafortune:badInput", "__rt_slice__: RM must be rows x 3 real singles, got %s",
                   what_of (Rv).c_str ());
  const octave_idx_type m = args(3).numel ();
  if (! args(1).is_single_type () || ! args(2).is_single_type () || args(1).iscomplex ()
      || args(2).iscomplex () || args(1).numel () != m || args(2).numel () != m)
    error_with_id ("lafortune:badInput", "__rt_slice__: A and B must be real singles, one per entry of K");
  if (! args(3).is_int32_type ())
    error_with_id ("lafortune:badInput", "__rt_slice__: K must be int32, got %s",
                   what_of (args(3)).c_str ());
  if (! args(4).is_real_scalar ())
    error_with_id ("lafortune:badInput", "__rt_slice__: NH must be a real scalar");
  const octave_value& cv = args(5);
  if (! cv.is_double_type () || cv.iscomplex () || cv.numel () != m)
    error_with_id ("lafortune:badInput", "__rt_slice__: COSI must be real doubles, one per entry of K, got %s",
                   what_of (cv).c_str ());

  Matrix rad (m, 3);
  oct_guard ("__rt_slice__", [&] ()
    {
      const FloatMatrix Rm = Rv.float_matrix_value ();
      const FloatNDArray a = args(1).float_array_value ();
      const FloatNDArray b = args(2).float_array_value ();
      const int32NDArray k = args(3).int32_array_value ();
      const double nhd = args(4).double_value ();
      const NDArray cosi = cv.array_value ();
      const octave_idx_type nr = Rm.rows ();
      const octave_idx_type nh = rt_table_step (nhd, nr);
      static_assert (sizeof (octave_int32) == sizeof (std::int32_t), "octave_int32 is an int32");
      rt_slice_rad (Rm.data (), nr, nh, reinterpret_cast<const std::int32_t *> (k.data ()),
                    a.data (), b.data (), cosi.data (), m, rad.fortran_vec ());
    });
  return ovl (rad);
}

/*
%!test
%! ## the slice table's radiance: single-precision interpolation, then times
%! ## cos ti in double, as slice_lookup
%! Rm = single (reshape (1:24, 8, 3) / 7);
%! a = single ([0.25; 0.5]); b = single ([0.75; 0]); k = int32 ([1; 2]); nh = 4; cosi = [0.5; 0.9];
%! v = ((1 - a) .* (1 - b)) .* Rm(k,:) + (a .* (1 - b)) .* Rm(k+1,:) ...
%!     + ((1 - a) .* b) .* Rm(k+nh,:) + (a .* b) .* Rm(k+nh+1,:);
%! assert (isequal (__rt_slice__ (Rm, a, b, k, nh, cosi), double (v) .* cosi));
%!error <RM must be> __rt_slice__ (ones (8, 3), single (0), single (0), int32 (1), 4, 1)
%!error <K must be int32> __rt_slice__ (single (ones (8, 3)), single (0), single (0), 1, 4, 1)
%!error <K must index> __rt_slice__ (single (ones (8, 3)), single (0), single (0), int32 (4), 4, 1)
%!error <COSI must be> __rt_slice__ (single (ones (8, 3)), single (0), single (0), int32 (1), 4, [1 2])
%!error <Invalid call> __rt_slice__ (1)
*/
