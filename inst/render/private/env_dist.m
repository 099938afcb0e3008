## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{D} =} env_dist (@var{light})
## The sampling distribution of an environment light (private, for
## @code{env_sample}, @code{scene_lights} and the tests): a piecewise-constant
## 2-D distribution over the map's texels in (theta, phi), each texel's
## probability proportional to its luminance times sin theta at its centre
## (as pbrt's image infinite light), a marginal over the rows and a
## conditional over the columns of each row.  Fields: @code{H}, @code{W},
## @code{rad} (H*W x 3, the map times the light's intensity, column-major),
## @code{p} (H x W texel probabilities), @code{cdf_row} (H+1),
## @code{cdf_col} (the rows' conditional CDFs, W+1 each, offset by the
## row's index so that one @code{lookup} serves every row), @code{rotation}
## (the map's turn about +y, degrees: @code{env_dirs}).
## @end deftypefn
function D = env_dist (light)
  M = light.map;
  [H, W, ~] = size (M);
  E = double (light.irradiance(:).') .* [1 1 1];
  Y = __lafortune_luminance__ (M);
  th = ((1:H).' - 0.5) / H * pi;
  w = Y .* sin (th);
  Z = sum (w(:));
  p = w / Z;
  pr = sum (p, 2);
  cdf_row = [0; cumsum(pr)];
  cdf_row /= cdf_row(end);
  C = [zeros(H, 1), cumsum(p, 2)];
  s = C(:,end);
  C(s > 0,:) ./= s(s > 0);
  C(s <= 0,:) = repmat ((0:W) / W, nnz (s <= 0), 1);    # never drawn
  C(:,end) = 1;
  C += (0:H-1).';
  D = struct ("H", H, "W", W, "rad", reshape (M, H * W, 3) .* E, "p", p,
              "cdf_row", cdf_row, "cdf_col", reshape (C.', [], 1),
              "rotation", light.rotation);
endfunction
