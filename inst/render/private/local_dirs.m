## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{wi}, @var{wo}, @var{X}, @var{Y}] =} local_dirs (@var{N}, @var{L}, @var{V})
## World directions toward the light @var{L} and the viewer @var{V} (m x 3,
## unit) at surfaces of unit normal @var{N}, in the local shading frame
## (z = N, x and y any orthonormal completion: isotropic materials do not
## depend on it), as unit @var{wi}, @var{wo} (private, for @code{rt_render}
## and @code{merl_scene}); @var{X}, @var{Y} the frame's tangents (for
## @code{mis_samples}, which turns local directions back to the world).
## @end deftypefn
function [wi, wo, X, Y] = local_dirs (N, L, V)
  a = repmat ([1 0 0], rows (N), 1);
  swap = abs (N(:,1)) > 0.9;
  a(swap,:) = repmat ([0 1 0], nnz (swap), 1);
  X = cross (a, N, 2);
  X ./= sqrt (sum (X .^ 2, 2));
  Y = cross (N, X, 2);
  wi = [sum(L .* X, 2), sum(L .* Y, 2), sum(L .* N, 2)];
  wo = [sum(V .* X, 2), sum(V .* Y, 2), sum(V .* N, 2)];
  wi ./= sqrt (sum (wi .^ 2, 2));
  wo ./= sqrt (sum (wo .^ 2, 2));
endfunction
