## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{rgb} =} plot_rgb (@var{v}, @var{cmap}, @var{lim}, @var{nan_rgb})
## False colour (private): the values @var{v} (H x W) through the colour map
## @var{cmap} (n x 3) over @var{lim} = [lo hi] (clamped), as an H x W x 3
## image in [0, 1]; NaN gets the colour @var{nan_rgb} (default light grey).
## @end deftypefn
function rgb = plot_rgb (v, cmap, lim, nan_rgb = [0.85 0.85 0.85])
  n = rows (cmap);
  t = (v - lim(1)) / (lim(2) - lim(1));
  i = round (min (max (t, 0), 1) * (n - 1)) + 1;
  bad = isnan (v);
  i(bad) = 1;
  rgb = zeros ([size(v) 3]);
  for c = 1:3
    x = cmap(i,c);
    x(bad) = nan_rgb(c);
    rgb(:,:,c) = reshape (x, size (v));
  endfor
endfunction
