## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{L}, @var{wt}] =} env_sample (@var{D}, @var{u}, @var{v})
## Directions drawn from an environment light's distribution @var{D}
## (@code{env_dist}) by the uniforms @var{u} (rows, by the marginal CDF) and
## @var{v} (the column within the row, by its conditional CDF), each
## continuous within its texel (private, for @code{light_samples}).
## @var{L} (n x 3, world, unit) and @var{wt} (n x 3), the radiance over the
## density in solid angle, so that the mean of wt f cos over the samples
## estimates the integral of the map's radiance times f cos.
## @end deftypefn
function [L, wt] = env_sample (D, u, v)
  [done, Lm, wt] = __lafortune_oct_call__ ("__env_sample__", "env_sample", D.cdf_row, D.cdf_col,
                                           D.p, D.rad, double (u(:)), double (v(:)));
  if (done)
    [~, R] = env_dirs ([], [], D.rotation);
    L = Lm * R.';
    return;
  endif
  H = D.H;
  W = D.W;
  u = min (max (u(:), 0), 1 - eps);
  v = min (max (v(:), 0), 1 - eps);
  r = lookup (D.cdf_row, u);                   # 1..H
  r = min (max (r, 1), H);
  fu = (u - D.cdf_row(r)) ./ max (D.cdf_row(r+1) - D.cdf_row(r), realmin);
  x = (r - 1) + v;
  C = D.cdf_col;
  j = lookup (C, x);                           # flat index into rows of W+1
  j = min (max (j, (r - 1) * (W + 1) + 1), r * (W + 1) - 1);
  c = j - (r - 1) * (W + 1);                   # 1..W
  fv = (x - C(j)) ./ max (C(j+1) - C(j), realmin);
  th = (r - 1 + min (max (fu, 0), 1)) / H * pi;
  ph = (c - 1 + min (max (fv, 0), 1)) / W * 2 * pi - pi;
  st = sin (th);
  [Lm, R] = env_dirs (th, ph, D.rotation);
  L = Lm * R.';
  k = r + (c - 1) * H;                         # column-major texel
  pk = D.p(k);
  ## density in solid angle: pk / (dtheta dphi sin theta)
  g = (pi / H) * (2 * pi / W) * st ./ max (pk, realmin);
  wt = D.rad(k,:) .* g;
endfunction
