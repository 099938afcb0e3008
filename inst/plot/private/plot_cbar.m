## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ha} =} plot_cbar (@var{hf}, @var{px}, @var{cmap}, @var{lim}, @var{label})
## @deftypefnx {} {@var{ha} =} plot_cbar (@dots{}, @var{ticks}, @var{ticklabels})
## A horizontal colour bar in its own axes of figure @var{hf} (private):
## @var{px} = [left bottom width height] in pixels, the colour map
## @var{cmap} spanning the values @var{lim} = [lo hi], ticks below it and
## @var{label} under them.  Drawn as an image, so that it looks the same in
## every graphics toolkit and does not resize other axes.
## @end deftypefn
function ha = plot_cbar (hf, px, cmap, lim, label, ticks = [], ticklabels = {})
  ha = plot_place (hf, px);
  n = rows (cmap);
  image (ha, linspace (lim(1), lim(2), n), [0 1], reshape (cmap, [1 n 3]));
  set (ha, "ydir", "normal", "ytick", [], "xlim", lim, "ylim", [-0.5 1.5],
       "tickdir", "out", "box", "on");
  if (! isempty (ticks))
    set (ha, "xtick", ticks);
    if (! isempty (ticklabels))
      set (ha, "xticklabel", ticklabels);
    endif
  endif
  xlabel (ha, label, "interpreter", "none");
endfunction
