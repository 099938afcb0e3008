// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_accum__: rt_render's sums of one chunk's samples into the pixels
// (its subfunction add_samples), compiled.  A render from the trace cache
// spends most of its time there: for every chunk, three accumarrays and
// three additions over the whole image.  add_samples stays the definition
// and the reference: it calls this when it is built, and the tests compare
// the two bit for bit.  The sums are those of the Octave code, in its
// order: each pixel's samples of the chunk summed from 0 in the order of
// their sample index (accumarray); add_samples adds the sums to the
// pixels' values (acc + sum; a pixel no sample reaches gets + 0 in the
// Octave code, which changes nothing, as the image holds no -0: it starts
// at +0 and only has sums added).  Built with -ffp-contract=off
// (src/Makefile).

#include <octave/oct.h>

#include "oct_guard.h"

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
Internal: the compiled sums of rt_render's private @code{add_samples} (see\n\
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
      const bool anybg = bg[0] != 0 || bg[1] != 0 || bg[2] != 0;
      // the order of the sums: the lit samples as given, and with a
      // background the misses too, stably sorted by sample index (as
      // add_samples's sort: a lit sample before a miss of the same index)
      std::vector<std::int64_t> j;     // >= 0: row of RAD; < 0: -(sample) - 1
      j.reserve (nl + (anybg ? m : 0));
      bool sorted = true;
      for (octave_idx_type i = 0; i < nl; i++)
        {
          const std::int32_t h = hs(i).value ();
          if (h < 1 || h > m)
            throw std::invalid_argument ("LITH must hold sample indices 1..numel (MISS)");
          if (i > 0 && h < hs(i-1).value ())
            sorted = false;
          j.push_back (i);
        }
      if (anybg)
        {
          auto key = [&] (std::int64_t x) -> std::int64_t
            { return x >= 0 ? static_cast<std::int64_t> (hs(x).value ()) - 1 : -x - 1; };
          std::vector<std::int64_t> mi;
          for (octave_idx_type i = 0; i < m; i++)
            if (miss(i))
              mi.push_back (-static_cast<std::int64_t> (i) - 1);
          if (sorted)                  // a merge of two sorted lists
            {
              std::vector<std::int64_t> out;
              out.reserve (j.size () + mi.size ());
              std::size_t a = 0, b = 0;
              while (a < j.size () || b < mi.size ())
                if (b == mi.size () || (a < j.size () && key (j[a]) <= key (mi[b])))
                  out.push_back (j[a++]);
                else
                  out.push_back (mi[b++]);
              j.swap (out);
            }
          else
            {
              j.insert (j.end (), mi.begin (), mi.end ());
              std::stable_sort (j.begin (), j.end (),
                                [&] (std::int64_t x, std::int64_t y) { return key (x) < key (y); });
            }
        }
      // each pixel's sum from 0, in the order of the samples; the chunk's
      // pixels are the SPAN from k0's on (mod NPIX)
      const std::uint64_t span = std::min<std::uint64_t> (m, npix);
      const std::uint64_t p0 = k0 % npix;
      std::vector<octave_idx_type> slot (span, -1);
      std::vector<std::uint64_t> touched;
      std::vector<double> s;
      touched.reserve (span);
      s.reserve (3 * span);
      const double *r = rad.data ();
      for (const std::int64_t x : j)
        {
          const std::uint64_t smp = x >= 0 ? static_cast<std::uint64_t> (hs(x).value ()) - 1
                                           : static_cast<std::uint64_t> (-x - 1);
          const std::uint64_t p = (k0 + smp) % npix;
          const std::uint64_t o = (p + npix - p0) % npix;
          octave_idx_type q = slot[o];
          if (q < 0)
            {
              q = slot[o] = touched.size ();
              touched.push_back (p);
              s.insert (s.end (), {0.0, 0.0, 0.0});
            }
          for (int c = 0; c < 3; c++)
            s[3 * q + c] += x >= 0 ? r[x + c * nl] : bg[c];
        }
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
