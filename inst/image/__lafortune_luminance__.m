## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{Y} =} __lafortune_luminance__ (@var{img})
## The luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709 primaries)
## of an H x W x 3 linear image or map (private: the one definition, for
## the tone map, FLIP's exposures and the environment light's sampling and
## median cut).
## @end deftypefn
function Y = __lafortune_luminance__ (img)
  Y = 0.2126 * img(:,:,1) + 0.7152 * img(:,:,2) + 0.0722 * img(:,:,3);
endfunction
