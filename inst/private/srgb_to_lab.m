## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{lab} =} srgb_to_lab (@var{rgb})
## Linear sRGB to CIELAB (private).  @var{rgb} is N x 3, linear (not
## gamma-encoded) values with the sRGB / Rec.@: 709 primaries and white
## D65; @var{lab} is N x 3 (L*, a*, b*), CIE 1976, relative to the white
## rgb = [1 1 1] (L* = 100, a* = b* = 0).  The RGB to XYZ matrix is derived
## from the primaries' and the white's chromaticities (IEC 61966-2-1),
## so that a grey has a* = b* = 0 up to rounding.
## @end deftypefn
function lab = srgb_to_lab (rgb)
  persistent M
  if (isempty (M))
    M = npm ([0.64 0.33; 0.30 0.60; 0.15 0.06], [0.3127 0.3290]);
  endif
  ## XYZ / white, per row: the white is M * [1 1 1]'
  xyz = rgb * (M ./ sum (M, 2))';
  d = 6 / 29;
  lo = xyz <= d^3;
  f = xyz;
  f(lo) = xyz(lo) / (3 * d^2) + 4 / 29;
  f(! lo) = cbrt (xyz(! lo));
  lab = [116 * f(:,2) - 16, 500 * (f(:,1) - f(:,2)), 200 * (f(:,2) - f(:,3))];
endfunction

## normalised primary matrix: RGB -> XYZ with Y(white) = 1
function M = npm (xy, w)
  P = [xy ./ xy(:,2), (1 - sum (xy, 2)) ./ xy(:,2)]';   # columns: XYZ of R, G, B at Y = 1
  W = [w(1) / w(2); 1; (1 - w(1) - w(2)) / w(2)];
  M = P .* (P \ W)';
endfunction
