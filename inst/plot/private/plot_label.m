## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ht} =} plot_label (@var{hf}, @var{x}, @var{y}, @var{txt}, @var{prop}, @var{val}, @dots{})
## One line of text at (@var{x}, @var{y}) pixels from the bottom-left corner
## of figure @var{hf} (private), centred on @var{x} with its top at @var{y}
## unless @var{prop}/@var{val} say otherwise, on an invisible axes covering
## the figure (made once per figure, tagged "lafortune_overlay").  For
## captions under images: one call per line, as the gnuplot toolkit cannot
## print labels of several lines.
## @end deftypefn
function ht = plot_label (hf, x, y, txt, varargin)
  ha = findobj (hf, "type", "axes", "tag", "lafortune_overlay");
  pos = get (hf, "position");
  if (isempty (ha))
    ha = axes ("parent", hf, "position", [0 0 1 1], "visible", "off",
               "xlim", [0 pos(3)], "ylim", [0 pos(4)], "tag", "lafortune_overlay");
  endif
  ht = text (ha(1), x, y, txt, "horizontalalignment", "center",
             "verticalalignment", "top", "interpreter", "none", varargin{:});
endfunction
