## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ha} =} plot_place (@var{hf}, @var{px})
## An axes in figure @var{hf} at @var{px} = [left bottom width height] in
## pixels from the figure's bottom-left corner (private), so that margins for
## labels and titles do not depend on the figure's size.
## @end deftypefn
function ha = plot_place (hf, px)
  pos = get (hf, "position");
  ha = axes ("parent", hf, "position", px ./ [pos(3) pos(4) pos(3) pos(4)]);
endfunction
