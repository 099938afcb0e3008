## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ha} =} plot_key (@var{hf}, @var{px}, @var{colors}, @var{labels})
## A legend drawn in its own region of figure @var{hf} (private): @var{px} =
## [left bottom width height] in pixels; one short line of each row of
## @var{colors} followed by its label, from the top down.  Unlike
## @code{legend (..., "location", "...outside")} it does not shrink the axes.
## @end deftypefn
function ha = plot_key (hf, px, colors, labels)
  ha = plot_place (hf, px);
  set (ha, "visible", "off", "xlim", [0 px(3)], "ylim", [0 px(4)]);
  hold (ha, "on");
  for k = 1:numel (labels)
    y = px(4) - 10 - 20 * (k - 1);
    plot (ha, [2 28], [y y], "-", "color", colors(k,:), "linewidth", 2);
    text (ha, 34, y, labels{k}, "verticalalignment", "middle", "interpreter", "none");
  endfor
  hold (ha, "off");
endfunction
