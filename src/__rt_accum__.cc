// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_accum__: rt_render's sums of one chunk's samples into the pixels
// (its subfunction chunk_sums), compiled (rt_shade.h's rt_chunk_sums): in
// Octave, three accumarrays over the whole image for every chunk.
// chunk_sums stays the definition and the reference: it calls this when it
// is built, and the tests compare the two bit for bit.  The sums are those of the Octave code, in its
// order: each pixel's samples of the chunk summed from 0 in the order of
// their sample index (accumarray); its caller adds the sums to the
// pixels' values (acc + sum; a pixel no sample reaches gets + 0 in the
// Octave code, which changes nothing, as the image holds no -0: it starts
// at +0 and only has sums added).  Built with -ffp-contract=off
// (src/Makefile).

#include <octave/oct.h>

#include "oct_guard.h"
#include "rt_shade.h"

#include <algorithm>
#include <stdexcept>
#include <cstdint>
#include <string>
#include <vector>

namespace
{
  bool
  real_double (const octave_value& v)
  {
    return v.is_double_type () && ! v.iscomplex () && ! v.issparse () && v.ndims () == 2;
  }
}

DEFUN_DLD (__rt_accum__, args, nargout,
           "-*- texinfo -*-\n\
@deftypefn {} {[@var{p}, @var{s}] =} __rt_accum__ (@var{npix}, @var{k0}, @var{lith}, @var{rad}, @var{miss}, @var{bg})\n\
Internal: the compiled sums of rt_render's private @code{chunk_sums} (see\n\
there).  The chunk of samples @var{k0}+1 @dots{} @var{k0}+M, M = numel\n\
(@var{miss}), sample k at pixel mod (k - 1, @var{npix}) + 1: the lit\n\
samples' indices in the chunk @var{lith} (int32, 1..M) with radiance\n\
@var{rad} (numel (@var{lith}) x 3 real doubles), the misses @var{miss}\n\
(logical) with the background @var{bg} (1 x 3) when it is not black.\n\
@var{p} holds the pixels the samples reach (a column, in the order of\n\
their first sample), @var{s} (numel (@var{p}) x 3) each one's sum.\n\
@end deftypefn")
{
  if (args.length () != 6)
    print_usage ();
  if (! args(0).is_real_scalar () || ! (args(0).double_value () >= 1))
    error_with_id ("lafortune:badInput", "__rt_accum__: NPIX must be a real scalar >= 1");
  if (! args(1).is_real_scalar () || ! (args(1).double_value () >= 0))
    error_with_id ("lafortune:badInput", "__rt_accum__: K0 must be a real scalar >= 0");
  const octave_value& hv = args(2);
  if (! hv.is_int32_type ())
    error_with_id ("lafortune:badInput", "__rt_accum__: LITH must be int32, got %s",
                   what_of (hv).c_str ());
  const octave_value& rv = args(3);
  if (! real_double (rv) || rv.columns () != 3 || rv.rows () != hv.numel ())
    error_with_id ("lafortune:badInput",
                   "__rt_accum__: RAD must be numel (LITH) x 3 real doubles, got %s",
                   what_of (rv).c_str ());
  if (! args(4).islogical ())
    error_with_id ("lafortune:badInput", "__rt_accum__: MISS must be logical, got %s",
                   what_of (args(4)).c_str ());
  const octave_value& bv = args(5);
  if (! real_double (bv) || bv.numel () != 3)
    error_with_id ("lafortune:badInput", "__rt_accum__: BG must be 3 real doubles, got %s",
                   what_of (bv).c_str ());

  ColumnVector pix;
  Matrix sums;
  oct_guard ("__rt_accum__", [&] ()
    {
      const std::uint64_t npix = static_cast<std::uint64_t> (args(0).double_value ());
      const std::uint64_t k0 = static_cast<std::uint64_t> (args(1).double_value ());
      const int32NDArray hs = hv.int32_array_value ();
      const Matrix rad = rv.matrix_value ();
      const boolNDArray miss = args(4).bool_array_value ();
      const Matrix bgm = bv.matrix_value ();
      const octave_idx_type m = miss.numel ();
      const octave_idx_type nl = hs.numel ();
      const double bg[3] = {bgm(0), bgm(1), bgm(2)};
      static_assert (sizeof (octave_int32) == sizeof (std::int32_t), "octave_int32 is an int32");
      std::vector<std::uint64_t> touched;
      std::vector<double> s;
      rt_chunk_sums (npix, k0, reinterpret_cast<const std::int32_t *> (hs.data ()), nl,
                     rad.data (), miss.data (), m, bg, touched, s);
      const octave_idx_type nt = touched.size ();
      pix = ColumnVector (nt);
      sums = Matrix (nt, 3);
      for (octave_idx_type q = 0; q < nt; q++)
        {
          pix(q) = static_cast<double> (touched[q]) + 1;
          for (int c = 0; c < 3; c++)
            sums(q, c) = s[3 * q + c];
        }
    });
  return ovl (pix, sums);
}

/*
%!error <Invalid call> __rt_accum__ (1)
%!error <NPIX must be> __rt_accum__ (0, 0, int32 (1), [1 2 3], false, [0 0 0])
%!error <LITH must be int32> __rt_accum__ (4, 0, 1, [1 2 3], false, [0 0 0])
%!error <RAD must be> __rt_accum__ (4, 0, int32 (1), [1 2], false, [0 0 0])
%!error <LITH must hold sample indices> __rt_accum__ (4, 0, int32 (2), [1 2 3], false, [0 0 0])
%!test
%! ## the sums of one chunk: pixels in the order of their first sample
%! [p, s] = __rt_accum__ (3, 1, int32 ([1; 1; 3; 4]), [1 1 1; 2 2 2; 3 3 3; 4 4 4], false (4, 1), [0 0 0]);
%! assert (p, [2; 1]);
%! assert (s, [7 7 7; 3 3 3]);
%! [p, s] = __rt_accum__ (3, 0, int32 (2), [1 2 3], [true; false; true], [0.5 0 0]);
%! assert (p, [1; 2; 3]);
%! assert (s, [0.5 0 0; 1 2 3; 0.5 0 0]);
*/
