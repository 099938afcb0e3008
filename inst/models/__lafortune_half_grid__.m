## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{h}, @var{u}, @var{th}] =} __lafortune_half_grid__ (@var{nu}, @var{np})
## The cell centres of the grid of half vectors that a MERL material's
## sampling table is made on (internal, for @code{density_table} and
## @code{__lafortune_density_m2__}): @var{nu} steps of u = sqrt (theta_h /
## (pi/2)) in [0, 1] (MERL's own scale of theta_h) by @var{np} steps of the
## azimuth phi in [0, pi], u down the rows, as one column each: @var{h}
## (nu np x 3, unit, about the normal, phi from the x axis), @var{u} and
## @var{th} (theta_h).
## @end deftypefn
function [h, u, th] = __lafortune_half_grid__ (nu, np)
  [PH, U] = meshgrid (((1:np) - 0.5) / np * pi, ((1:nu) - 0.5) / nu);
  u = U(:);
  th = pi / 2 * u .^ 2;
  h = [sin(th) .* cos(PH(:)), sin(th) .* sin(PH(:)), cos(th)];
endfunction

%!test
%! [h, u, th] = __lafortune_half_grid__ (4, 3);
%! assert (size (h), [12 3]);
%! assert (sum (h .^ 2, 2), ones (12, 1), 1e-15);
%! assert (u(1:4), [0.125; 0.375; 0.625; 0.875]);
%! assert (th, pi / 2 * u .^ 2);
%! assert (acos (h(:,3)), th, 1e-12);
