## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{f} =} cook_torrance (@var{p}, @var{wi}, @var{wo})
## Cook-Torrance BRDF (private): Beckmann distribution of roughness p.m,
## V-groove shadowing/masking, Schlick Fresnel with normal-incidence
## reflectance p.F0, specular scale p.rho_s (1 x 3) and diffuse p.rho_d
## (1 x 3).  N x 3 unit directions above the horizon; returns N x 3.
## @end deftypefn
function f = cook_torrance (p, wi, wo)
  h = wi + wo;
  h ./= sqrt (sum (h .^ 2, 2));
  ci = wi(:,3); co = wo(:,3); ch = h(:,3);
  voh = sum (wo .* h, 2);
  t2 = (1 - ch .^ 2) ./ ch .^ 2;
  D = exp (-t2 / p.m ^ 2) ./ (p.m ^ 2 * ch .^ 4);
  G = min (1, min (2 * ch .* co ./ voh, 2 * ch .* ci ./ voh));
  cd = sum (wi .* h, 2);
  F = p.F0 + (1 - p.F0) * (1 - cd) .^ 5;
  spec = D .* G .* F ./ (pi * ci .* co);
  f = p.rho_d / pi + spec .* p.rho_s;
endfunction
