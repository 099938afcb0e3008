## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{ht} =} plot_heading (@var{hf}, @var{txt})
## @deftypefnx {} {@var{ht} =} plot_heading (@var{hf}, @var{txt}, @var{y}, @var{bold})
## A line of text across figure @var{hf} (private), centred, its top @var{y}
## pixels below the figure's top edge (default 6), bold (default) or not, in
## an invisible axes that covers the figure: a heading, or with a large
## @var{y} a caption at the bottom.  A line too long for the figure's width
## is set in a smaller font (down to 6 points) so that none of it is cut
## off.  Returns the text's handle.
## @end deftypefn
function ht = plot_heading (hf, txt, y = 6, bold = true)
  pos = get (hf, "position");
  ha = axes ("parent", hf, "position", [0 0 1 1], "visible", "off",
             "xlim", [0 1], "ylim", [0 1]);
  w = "normal";
  fs = 10;
  if (bold)
    w = "bold";
    fs = 12;
  endif
  ht = text (ha, 0.5, 1 - y / pos(4), txt, "horizontalalignment", "center",
             "verticalalignment", "top", "fontsize", fs, "fontweight", w,
             "interpreter", "none");
  ## the width it will have in the picture, as a share of the figure's: the
  ## gnuplot toolkit's cairo printer draws text wider than the extent that
  ## Octave's own font renderer reports (printed_scale)
  e = get (ht, "extent");
  k = e(3) * printed_scale (hf);
  if (k > 0.96)
    set (ht, "fontsize", max (6, floor (2 * fs * 0.96 / k) / 2));
  endif
endfunction

## how much wider than its extent text is printed by the toolkit of HF
function k = printed_scale (hf)
  k = 1.05;
  if (strcmp (get (hf, "__graphics_toolkit__"), "gnuplot"))
    k = 1.6;
  endif
endfunction
