// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_slice_sum__: a whole render from rt_render's trace cache in slice
// mode, compiled: for each cached chunk in turn its shading from the slice
// table (slice_rad) and its sums into the pixels (chunk_sums), as
// rt_render's loop over the chunks does, in one call instead of two per
// chunk (a fit's render from the measured render's trace is 256 chunks).
// rt_render's loop stays the definition and the reference (and the
// fallback): the same operations in the same order (rt_shade.h, shared with
// __rt_slice__ and __rt_accum__), and each chunk's pixel sums added to the
// image as acc(p,:) += s does.

#include <octave/oct.h>

#include "oct_guard.h"
#include "rt_shade.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  // field F of the scalar struct S, or an error naming chunk I
  octave_value
  field_of (const octave_scalar_map& s, const char *f, octave_idx_type i)
  {
    if (! s.isfield (f))
      throw std::invalid_argument ("chunk " + std::to_string (i + 1) + " has no field " + f);
    return s.getfield (f);
  }
}

DEFUN_DLD (__rt_slice_sum__, args, ,
           "-*- texinfo -*-\n\
@deftypefn {} {@var{acc} =} __rt_slice_sum__ (@var{Rm}, @var{chunks}, @var{chunk}, @var{total}, @var{npix}, @var{bg})\n\
Internal: the compiled render of rt_render from its trace cache in slice\n\
mode (see there): the image's sums @var{acc} (@var{npix} x 3, from 0) of\n\
the cached chunks @var{chunks} (a cell of structs with fields @code{h},\n\
@code{w}, @code{cosi}, @code{miss}) of @var{chunk} samples each, of\n\
@var{total} in all, shaded from the slice table @var{Rm} (single, rows x\n\
3), with the background @var{bg} (1 x 3).\n\
@end deftypefn")
{
  if (args.length () != 6)
    print_usage ();
  const octave_value& Rv = args(0);
  if (! rt_table_ok (Rv))
    error_with_id ("lafortune:badInput", "__rt_slice_sum__: RM must be rows x 3 real singles, got %s",
                   what_of (Rv).c_str ());
  if (! args(1).iscell ())
    error_with_id ("lafortune:badInput", "__rt_slice_sum__: CHUNKS must be a cell array, got %s",
                   what_of (args(1)).c_str ());
  for (int i : {2, 3, 4})
    if (! args(i).is_real_scalar () || ! (args(i).double_value () >= 1)
        || ! (args(i).double_value () < 9.0e15)
        || args(i).double_value () != std::floor (args(i).double_value ()))
      error_with_id ("lafortune:badInput",
                     "__rt_slice_sum__: CHUNK, TOTAL and NPIX must be whole numbers >= 1");
  const octave_value& bv = args(5);
  if (! bv.is_double_type () || bv.iscomplex () || bv.numel () != 3)
    error_with_id ("lafortune:badInput", "__rt_slice_sum__: BG must be 3 real doubles, got %s",
                   what_of (bv).c_str ());

  const std::uint64_t npix = static_cast<std::uint64_t> (args(4).double_value ());
  Matrix acc (npix, 3, 0.0);
  oct_guard ("__rt_slice_sum__", [&] ()
    {
      static_assert (sizeof (octave_int32) == sizeof (std::int32_t), "octave_int32 is an int32");
      const FloatMatrix Rm = Rv.float_matrix_value ();
      const octave_idx_type nr = Rm.rows ();
      const Cell chunks = args(1).cell_value ();
      const std::uint64_t chunk = static_cast<std::uint64_t> (args(2).double_value ());
      const std::uint64_t total = static_cast<std::uint64_t> (args(3).double_value ());
      const octave_idx_type nc = chunks.numel ();
      if (static_cast<std::uint64_t> (nc) != (total + chunk - 1) / chunk)
        throw std::invalid_argument ("CHUNKS must hold ceil (TOTAL / CHUNK) chunks");
      const Matrix bgm = bv.matrix_value ();
      const double bg[3] = {bgm(0), bgm(1), bgm(2)};
      double *A = acc.fortran_vec ();
      std::vector<std::uint64_t> touched;
      std::vector<double> s, rad;
      for (octave_idx_type i = 0; i < nc; i++)
        {
          const std::uint64_t k0 = static_cast<std::uint64_t> (i) * chunk;
          const octave_idx_type m = static_cast<octave_idx_type> (std::min (chunk, total - k0));
          if (! chunks(i).isstruct () || chunks(i).numel () != 1)
            throw std::invalid_argument ("chunk " + std::to_string (i + 1) + " must be a struct");
          const octave_scalar_map T = chunks(i).scalar_map_value ();
          const octave_value hv = field_of (T, "h", i);
          const octave_value wv = field_of (T, "w", i);
          const octave_value cv = field_of (T, "cosi", i);
          const octave_value mv = field_of (T, "miss", i);
          if (! wv.isstruct () || wv.numel () != 1)
            throw std::invalid_argument ("chunk " + std::to_string (i + 1) + ": w must be a struct");
          const octave_scalar_map w = wv.scalar_map_value ();
          const octave_value av = field_of (w, "a", i), bwv = field_of (w, "b", i);
          const octave_value kv = field_of (w, "k", i), nhv = field_of (w, "nh", i);
          const octave_idx_type nl = hv.numel ();
          if (! hv.is_int32_type () || ! kv.is_int32_type () || kv.numel () != nl
              || ! av.is_single_type () || av.iscomplex () || av.numel () != nl
              || ! bwv.is_single_type () || bwv.iscomplex () || bwv.numel () != nl
              || ! cv.is_double_type () || cv.iscomplex () || cv.numel () != nl
              || ! mv.islogical () || mv.numel () != m || ! nhv.is_real_scalar ())
            throw std::invalid_argument ("chunk " + std::to_string (i + 1)
                                         + ": h, w.k (int32), w.a, w.b (single), cosi (double) must have one entry per lit sample, miss (logical) one per sample");
          const octave_idx_type nh = rt_table_step (nhv.double_value (), nr);
          const int32NDArray h = hv.int32_array_value ();
          const int32NDArray k = kv.int32_array_value ();
          const FloatNDArray a = av.float_array_value ();
          const FloatNDArray b = bwv.float_array_value ();
          const NDArray cosi = cv.array_value ();
          const boolNDArray miss = mv.bool_array_value ();
          // slice_rad, then chunk_sums: the chunk's sums added to the image
          rad.resize (3 * nl);
          rt_slice_rad (Rm.data (), nr, nh,
                        reinterpret_cast<const std::int32_t *> (k.data ()), a.data (), b.data (),
                        cosi.data (), nl, rad.data ());
          rt_chunk_sums (npix, k0, reinterpret_cast<const std::int32_t *> (h.data ()), nl,
                         rad.data (), miss.data (), m, bg, touched, s);
          for (std::size_t q = 0; q < touched.size (); q++)
            for (int c = 0; c < 3; c++)
              A[touched[q] + c * npix] += s[3 * q + c];
        }
    });
  return ovl (acc);
}

/*
%!error <Invalid call> __rt_slice_sum__ (1)
%!error <RM must be> __rt_slice_sum__ (ones (8, 3), {}, 1, 1, 1, [0 0 0])
%!error <CHUNKS must be a cell> __rt_slice_sum__ (single (ones (8, 3)), 1, 1, 1, 1, [0 0 0])
%!error <CHUNK, TOTAL and NPIX> __rt_slice_sum__ (single (ones (8, 3)), {}, 0, 1, 1, [0 0 0])
%!error <must hold ceil> __rt_slice_sum__ (single (ones (8, 3)), {}, 2, 3, 4, [0 0 0])
%!error <has no field cosi> __rt_slice_sum__ (single (ones (8, 3)), {struct("h", int32 (1), "w", 1, "miss", false)}, 2, 1, 4, [0 0 0])
%!error <one entry per lit sample> __rt_slice_sum__ (single (ones (8, 3)), {struct("h", int32 (1), "w", struct ("a", single (0), "b", single (0), "k", int32 (1), "nh", 2), "cosi", 1, "miss", [false false])}, 2, 1, 4, [0 0 0])
%!test
%! ## two chunks of 3 samples on 4 pixels (the second wraps around), one lit
%! ## sample each plus a miss with a background: the sums of slice_rad's
%! ## values and the background, chunk by chunk
%! Rm = single (reshape (1:24, 8, 3) / 7);
%! w = struct ("a", single (0.25), "b", single (0.5), "k", int32 (2), "nh", 4);
%! c1 = struct ("h", int32 (2), "w", w, "cosi", 0.5, "miss", [true; false; false]);
%! c2 = struct ("h", int32 (1), "w", w, "cosi", 0.25, "miss", [false; true; false]);
%! acc = __rt_slice_sum__ (Rm, {c1, c2}, 3, 6, 4, [0.1 0.2 0.3]);
%! v = double (((1 - w.a) * (1 - w.b)) * Rm(2,:) + (w.a * (1 - w.b)) * Rm(3,:) ...
%!             + ((1 - w.a) * w.b) * Rm(6,:) + (w.a * w.b) * Rm(7,:));
%! e = zeros (4, 3);
%! e(1,:) = [0.1 0.2 0.3] + [0.1 0.2 0.3];   # samples 1 (miss) and 5 (miss)
%! e(2,:) = v * 0.5;                          # sample 2
%! e(4,:) = v * 0.25;                         # sample 4
%! assert (acc, e, 1e-15);
*/
