## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{p}, @var{rad}] =} env_pdf (@var{D}, @var{L})
## The density in solid angle with which @code{env_sample} draws the world
## directions @var{L} (n x 3, unit) from the environment light's
## distribution @var{D} (@code{env_dist}), and the map's radiance there
## (n x 3, the texel's, as @code{env_sample} weighs it; private, for the
## multiple importance sampling of @code{scene_trace}): the texel's
## probability over dtheta dphi sin theta.
## @end deftypefn
function [p, rad] = env_pdf (D, L)
  [~, R] = env_dirs ([], [], D.rotation);
  Lm = L * R;                                  # world to the map's frame
  th = acos (min (max (Lm(:,2), -1), 1));
  ph = atan2 (Lm(:,1), -Lm(:,3));
  r = min (max (floor (th / pi * D.H) + 1, 1), D.H);
  c = min (max (floor ((ph + pi) / (2 * pi) * D.W) + 1, 1), D.W);
  k = r + (c - 1) * D.H;
  st = max (sin (th), 1e-12);
  p = D.p(k) ./ ((pi / D.H) * (2 * pi / D.W) * st);
  rad = D.rad(k,:);
endfunction
