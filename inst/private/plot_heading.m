## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ht} =} plot_heading (@var{hf}, @var{txt}, @var{top})
## A heading across the top of figure @var{hf} (private): @var{txt} centred,
## its top @var{top} pixels (default 6) below the figure's top edge, in an
## invisible axes that covers the figure.  Returns the text's handle.
## @end deftypefn
function ht = plot_heading (hf, txt, top = 6)
  pos = get (hf, "position");
  ha = axes ("parent", hf, "position", [0 0 1 1], "visible", "off",
             "xlim", [0 1], "ylim", [0 1]);
  ht = text (ha, 0.5, 1 - top / pos(4), txt, "horizontalalignment", "center",
             "verticalalignment", "top", "fontsize", 12, "fontweight", "bold",
             "interpreter", "none");
endfunction
