## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} srgb_xyz ()
## The 3 x 3 matrix from linear sRGB (Rec.@: 709 primaries, white D65) to
## CIE XYZ divided by the white's XYZ (private): @code{xyz_w = T * rgb},
## so that rgb = [1 1 1] gives [1 1 1].  It is derived from the primaries'
## and the white's chromaticities (IEC 61966-2-1), so that a grey maps to
## equal X/Xw = Y/Yw = Z/Zw up to rounding.  The one definition of this
## matrix: CIELAB (srgb_to_lab) and FLIP's colour spaces (img_flip) use it.
## @end deftypefn
function T = srgb_xyz ()
  persistent M
  if (isempty (M))
    xy = [0.64 0.33; 0.30 0.60; 0.15 0.06];
    w = [0.3127 0.3290];
    P = [xy ./ xy(:,2), (1 - sum (xy, 2)) ./ xy(:,2)]';   # columns: XYZ of R, G, B at Y = 1
    W = [w(1) / w(2); 1; (1 - w(1) - w(2)) / w(2)];
    M = (P .* (P \ W)') ./ W;
  endif
  T = M;
endfunction
