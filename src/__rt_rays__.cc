// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// __rt_rays__: the camera rays of pixel samples, rt_render's and
// merl_scene's private sample_rays (pixel_samples, then the one camera's
// __lafortune_camera_rays__), compiled: a render of 128 samples per pixel
// makes 16 million rays, each a dozen element-wise Octave operations.  The
// two Octave functions stay the definition and the reference: sample_rays
// calls this through __lafortune_oct_call__, and the tests compare the two
// bit for bit.  Every floating-point operation is the one the Octave code
// makes, in its order (built with -ffp-contract=off, src/Makefile); the
// integer parts (mod and floor of whole numbers below 2^53) are exact in
// either.  The random offsets stay Octave's (rand).

#include <octave/oct.h>

#include "oct_guard.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

DEFUN_DLD (__rt_rays__, args, nargout,
           "-*- texinfo -*-\n\
@deftypefn {} {[@var{O}, @var{D}] =} __rt_rays__ (@var{H}, @var{W}, @var{k}, @var{spp}, @var{j}, @var{persp}, @var{eye}, @var{f}, @var{r}, @var{u}, @var{w}, @var{h})\n\
Internal: the compiled rays of the pixel samples @var{k} (0-based, real\n\
whole numbers below 2^53) of an @var{H} x @var{W} image with @var{spp}\n\
samples per pixel at the offsets @var{j} (numel (@var{k}) x 2), as\n\
pixel_samples and __lafortune_camera_rays__ make them with the camera\n\
frame @var{eye}, @var{f}, @var{r}, @var{u} (1 x 3) and the view's size\n\
@var{w} x @var{h}; @var{persp} true for a perspective camera.  @var{O}\n\
and @var{D} are numel (@var{k}) x 3.\n\
@end deftypefn")
{
  if (args.length () != 12)
    print_usage ();
  for (int i : {0, 1, 3})
    if (! args(i).is_real_scalar () || ! (args(i).double_value () >= 1)
        || args(i).double_value () != std::floor (args(i).double_value ())
        || ! (args(i).double_value () < 9.0e15))
      error_with_id ("lafortune:badInput", "__rt_rays__: H, W and SPP must be whole numbers >= 1");
  const octave_value& kv = args(2);
  if (! kv.is_double_type () || kv.iscomplex () || kv.issparse ())
    error_with_id ("lafortune:badInput", "__rt_rays__: K must be real doubles, got %s",
                   what_of (kv).c_str ());
  const octave_idx_type m = kv.numel ();
  const octave_value& jv = args(4);
  if (! jv.is_double_type () || jv.iscomplex () || jv.issparse () || jv.ndims () != 2
      || jv.rows () != m || jv.columns () != 2)
    error_with_id ("lafortune:badInput", "__rt_rays__: J must be numel (K) x 2 real doubles, got %s",
                   what_of (jv).c_str ());
  if (! args(5).is_real_scalar () && ! args(5).is_bool_scalar ())
    error_with_id ("lafortune:badInput", "__rt_rays__: PERSP must be true or false");
  for (int i = 6; i <= 9; i++)
    if (! args(i).is_double_type () || args(i).iscomplex () || args(i).numel () != 3)
      error_with_id ("lafortune:badInput", "__rt_rays__: EYE, F, R and U must be 3 real doubles");
  if (! args(10).is_real_scalar () || ! args(11).is_real_scalar ())
    error_with_id ("lafortune:badInput", "__rt_rays__: W and H (the view's size) must be real scalars");

  Matrix O (m, 3), D (m, 3);
  oct_guard ("__rt_rays__", [&] ()
    {
      const std::uint64_t H = static_cast<std::uint64_t> (args(0).double_value ());
      const std::uint64_t W = static_cast<std::uint64_t> (args(1).double_value ());
      const std::uint64_t spp = static_cast<std::uint64_t> (args(3).double_value ());
      const NDArray k = kv.array_value ();
      const Matrix j = jv.matrix_value ();
      const bool persp = args(5).bool_value ();
      const NDArray E = args(6).array_value (), F = args(7).array_value ();
      const NDArray R = args(8).array_value (), U = args(9).array_value ();
      const double vw = args(10).double_value ();
      const double vh = args(11).double_value ();
      const double dH = static_cast<double> (H), dW = static_cast<double> (W);
      const std::uint64_t npix = H * W;
      // pixel_samples's cells: ny the largest divisor of spp <= sqrt (spp)
      std::uint64_t ny = spp;
      for (std::uint64_t d = static_cast<std::uint64_t> (std::floor (std::sqrt (static_cast<double> (spp))));
           d >= 1; d--)
        if (spp % d == 0)
          {
            ny = d;
            break;
          }
      const std::uint64_t nx = spp / ny;
      const double dnx = static_cast<double> (nx), dny = static_cast<double> (ny);
      double *o = O.fortran_vec ();
      double *dd = D.fortran_vec ();
      for (octave_idx_type i = 0; i < m; i++)
        {
          const double kd = k(i);
          if (! (kd >= 0 && kd < 9.0e15 && kd == std::floor (kd)))
            throw std::invalid_argument ("K must hold whole numbers >= 0 below 2^53");
          const std::uint64_t ki = static_cast<std::uint64_t> (kd);
          const std::uint64_t p = ki % npix;
          const std::uint64_t s = ki / npix;
          const double row = static_cast<double> (p % H);
          const double col = static_cast<double> (p / H);
          const double ms = static_cast<double> (s % nx);
          const double fs = static_cast<double> (s / nx);
          // x = (c + (mod (s, nx) + j1) / nx) / W - 0.5
          const double x = (col + (ms + j(i, 0)) / dnx) / dW - 0.5;
          // y = 0.5 - (r + (floor (s / nx) + j2) / ny) / H
          const double y = 0.5 - (row + (fs + j(i, 1)) / dny) / dH;
          const double xw = x * vw;
          const double yh = y * vh;
          if (! persp)
            {
              // O = eye + (x w) .* r + (y h) .* u;  D = f
              for (int c = 0; c < 3; c++)
                {
                  o[i + c * m] = (E(c) + xw * R(c)) + yh * U(c);
                  dd[i + c * m] = F(c);
                }
            }
          else
            {
              // D = f + (x w) .* r + (y h) .* u;  D ./= sqrt (sum (D .^ 2, 2))
              double v[3];
              for (int c = 0; c < 3; c++)
                v[c] = (F(c) + xw * R(c)) + yh * U(c);
              const double len = std::sqrt ((v[0] * v[0] + v[1] * v[1]) + v[2] * v[2]);
              for (int c = 0; c < 3; c++)
                {
                  dd[i + c * m] = v[c] / len;
                  o[i + c * m] = E(c);
                }
            }
        }
    });
  return ovl (O, D);
}

/*
%!test
%! ## pixel samples and rays of both cameras: the Octave code's, bit for bit
%! ## (test/test_core_engines.m compares whole renders)
%! k = [0; 1; 5; 11; 12; 13; 47; 1e6 + 3];
%! j = [0 0; 0.5 0.5; 0.999 0.001; 0.25 0.75; 0.1 0.9; 0.3 0.3; 0.7 0.2; 0.6 0.4];
%! H = 3; W = 4; spp = 12;
%! npix = H * W; p = mod (k, npix); s = floor (k / npix); ny = 3; nx = 4;
%! x = (floor (p / H) + (mod (s, nx) + j(:,1)) / nx) / W - 0.5;
%! y = 0.5 - (mod (p, H) + (floor (s / nx) + j(:,2)) / ny) / H;
%! e = [0.1 0.2 5]; f = [0.01 -0.02 -1]; f /= norm (f); r = cross (f, [0 1 0]); r /= norm (r); u = cross (r, f);
%! [O, D] = __rt_rays__ (H, W, k, spp, j, false, e, f, r, u, 2.5, 1.7);
%! assert (isequal (O, e + (x * 2.5) .* r + (y * 1.7) .* u));
%! assert (isequal (D, repmat (f, numel (k), 1)));
%! [O, D] = __rt_rays__ (H, W, k, spp, j, true, e, f, r, u, 2.5, 1.7);
%! Dp = f + (x * 2.5) .* r + (y * 1.7) .* u;
%! Dp ./= sqrt (sum (Dp .^ 2, 2));
%! assert (isequal (D, Dp));
%! assert (isequal (O, repmat (e, numel (k), 1)));
%!error <Invalid call> __rt_rays__ (1)
%!error <H, W and SPP must be> __rt_rays__ (0, 4, 0, 1, [0 0], false, [0 0 0], [0 0 1], [1 0 0], [0 1 0], 1, 1)
%!error <K must be real doubles> __rt_rays__ (3, 4, int32 (0), 1, [0 0], false, [0 0 0], [0 0 1], [1 0 0], [0 1 0], 1, 1)
%!error <J must be> __rt_rays__ (3, 4, [0; 1], 1, [0 0], false, [0 0 0], [0 0 1], [1 0 0], [0 1 0], 1, 1)
%!error <K must hold whole numbers> __rt_rays__ (3, 4, -1, 1, [0 0], false, [0 0 0], [0 0 1], [1 0 0], [0 1 0], 1, 1)
%!error <K must hold whole numbers> __rt_rays__ (3, 4, 0.5, 1, [0 0], false, [0 0 0], [0 0 1], [1 0 0], [0 1 0], 1, 1)
%!error <EYE, F, R and U> __rt_rays__ (3, 4, 0, 1, [0 0], false, [0 0], [0 0 1], [1 0 0], [0 1 0], 1, 1)
*/
