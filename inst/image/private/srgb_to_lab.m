## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{lab} =} srgb_to_lab (@var{rgb})
## Linear sRGB to CIELAB (private).  @var{rgb} is N x 3, linear (not
## gamma-encoded) values with the sRGB / Rec.@: 709 primaries and white
## D65; @var{lab} is N x 3 (L*, a*, b*), CIE 1976, relative to the white
## rgb = [1 1 1] (L* = 100, a* = b* = 0), through srgb_xyz.
## @end deftypefn
function lab = srgb_to_lab (rgb)
  xyz = rgb * srgb_xyz ()';           # XYZ / white, per row
  d = 6 / 29;
  lo = xyz <= d^3;
  f = xyz;
  f(lo) = xyz(lo) / (3 * d^2) + 4 / 29;
  f(! lo) = cbrt (xyz(! lo));
  lab = [116 * f(:,2) - 16, 500 * (f(:,1) - f(:,2)), 200 * (f(:,2) - f(:,3))];
endfunction
