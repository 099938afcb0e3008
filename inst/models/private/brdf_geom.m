## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{G} =} brdf_geom (@var{X})
## The angles an isotropic model sees, from @var{X} = [cos theta_i, cos
## theta_o, wi.wo] (N x 3, both cosines > 0): @code{G.ci}, @code{G.co},
## @code{G.ch} (cos theta_h, H = normalize (wi + wo)), @code{G.t2} (tan^2
## theta_h, without the cancellation of 1/ch^2 - 1 near the mirror
## direction), @code{G.cd} (cos theta_d = wi.H = wo.H), @code{G.hh} (|wi +
## wo|^2) and @code{G.s5} ((1 - cos theta_d)^5, Schlick's Fresnel weight).
## The one place the physically based models (private @code{brdf_*.m})
## take their angles from.
## @end deftypefn

function G = brdf_geom (X)
  ci = X(:,1);
  co = X(:,2);
  hh = max (2 + 2 * X(:,3), realmin);          # |wi + wo|^2
  s = ci + co;
  G.ci = ci;
  G.co = co;
  G.hh = hh;
  G.ch = s ./ sqrt (hh);
  G.t2 = max (hh - s .^ 2, 0) ./ s .^ 2;       # sin^2 / cos^2 of theta_h
  G.cd = min (sqrt (hh) / 2, 1);
  G.s5 = (1 - G.cd) .^ 5;
endfunction
