## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{m2} =} __lafortune_density_m2__ (@var{D})
## How much sharper a sampling density @var{D} (@code{brdf_density}) is
## than the cosine-weighted hemisphere (internal, for @code{brdf_density},
## which keeps it with a MERL material's table, and @code{rt_render}'s
## share of BRDF samples): the median over eight views (theta_o in [0, 90)
## degrees) of the second moment of the density against the cosine, the
## integral of p^2 / (cos theta_i / pi) over the hemisphere, by midpoint
## quadrature on a grid of half vectors (48 steps of sqrt (theta_h) by 32
## of their azimuth, both signs, as the tables of @code{brdf_density} are
## made).  It is 1 for the cosine itself and grows with the density's
## peaks; a non-finite value gives 1.
## @end deftypefn
function m2 = __lafortune_density_m2__ (D)
  if (isfield (D.model, "m2"))
    m2 = D.model.m2;
    return;
  endif
  nu = 48;
  np = 32;
  [h, U, th] = __lafortune_half_grid__ (nu, np);
  dA = pi * U .* sin (th) * (1 / nu) * (2 * pi / np);   # both signs of phi
  to = ((1:8) - 0.5) / 8 * pi / 2;
  m = zeros (1, numel (to));
  for k = 1:numel (to)
    wo = [sin(to(k)), 0, cos(to(k))];
    c = h * wo.';
    wi = 2 * c .* h - wo;
    ok = wi(:,3) > 1e-6 & c > 0;
    p = brdf_pdf (D, repmat (wo, sum (ok), 1), wi(ok,:));
    m(k) = sum (p .^ 2 ./ (wi(ok,3) / pi) .* (4 * c(ok) .* dA(ok)));
  endfor
  m2 = median (m);
  if (! (isfinite (m2) && m2 > 0))
    m2 = 1;
  endif
endfunction

%!test
%! ## the cosine itself: 1; a sharp lobe: far more
%! lam = struct ("rho_d", [0.5 0.5 0.5], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! assert (__lafortune_density_m2__ (brdf_density (lam)), 1, 2e-3);
%! sharp = struct ("rho_d", [0.02 0.02 0.02], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [300 300 300]);
%! assert (__lafortune_density_m2__ (brdf_density (sharp)) > 20);
%! ## a MERL material's table keeps it
%! [D, T] = brdf_density (merl_standin ("green-metallic-paint"));
%! assert (T.m2, __lafortune_density_m2__ (D));
%! assert (T.m2 > 1.5);
