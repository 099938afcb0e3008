## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{itp} =} ictcp (@var{rgb})
## ICtCp of ITU-R BT.2100 (PQ) (private).  @var{rgb} is N x 3 linear light
## with the Rec.@: 709 / sRGB primaries (white D65), in absolute units:
## cd/m^2.  It is converted to BT.2020 RGB (through XYZ, matrices derived
## from the primaries' chromaticities), to LMS by BT.2100's matrix
## [1688 2146 262; 683 2951 462; 99 309 3688] / 4096, to L'M'S' by the PQ
## curve of SMPTE ST 2084 (normalised to 10000 cd/m^2; negative light is
## taken as 0), and to @var{itp} = [I Ct Cp] (N x 3) by
## [2048 2048 0; 6610 -13613 7003; 17933 -17390 -543] / 4096.
## @end deftypefn
function itp = ictcp (rgb)
  persistent A
  if (isempty (A))
    w = [0.3127 0.3290];
    R709 = npm ([0.64 0.33; 0.30 0.60; 0.15 0.06], w);
    R2020 = npm ([0.708 0.292; 0.170 0.797; 0.131 0.046], w);
    A = [1688 2146 262; 683 2951 462; 99 309 3688] / 4096 * (R2020 \ R709);
  endif
  lms = max (rgb * A' / 10000, 0);
  m1 = 2610 / 16384;  m2 = 2523 / 4096 * 128;
  c1 = 3424 / 4096;  c2 = 2413 / 4096 * 32;  c3 = 2392 / 4096 * 32;
  p = lms .^ m1;
  lms = ((c1 + c2 * p) ./ (1 + c3 * p)) .^ m2;
  itp = lms * ([2048 2048 0; 6610 -13613 7003; 17933 -17390 -543] / 4096)';
endfunction

## normalised primary matrix: RGB -> XYZ with Y(white) = 1
function M = npm (xy, w)
  P = [xy ./ xy(:,2), (1 - sum (xy, 2)) ./ xy(:,2)]';
  W = [w(1) / w(2); 1; (1 - w(1) - w(2)) / w(2)];
  M = P .* (P \ W)';
endfunction
