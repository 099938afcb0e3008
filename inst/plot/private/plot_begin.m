## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{hf} =} plot_begin (@var{fname}, @var{size})
## A new figure for one of the plot_* functions (private).  @var{size} =
## [width height] in pixels.  The figure is invisible when there is no
## display (octave-cli without DISPLAY: the gnuplot toolkit, printed with
## @code{print -dpngcairo}).  Octave draws every axes with its default font
## (FreeSans.otf of the Debian package fonts-freefont-otf, which
## octave-common only recommends); when it cannot, this fails early with
## @code{lafortune:noFonts} instead of Octave's "unable to create graphics
## handle".
## @end deftypefn
function hf = plot_begin (fname, sz)
  warning ("off", "Octave:gnuplot-graphics", "local");   # the toolkit's nag, here only
  args = {"position", [40 40 sz], "color", "w"};
  if (! isguirunning () && isempty (getenv ("DISPLAY")))
    args(end+1:end+2) = {"visible", "off"};
  endif
  hf = figure (args{:});
  try
    delete (axes ("parent", hf));
  catch err
    close (hf);
    if (! isempty (strfind (err.message, "font"))
        || ! isempty (strfind (err.message, "bounding box")))
      error ("lafortune:noFonts",
             ["%s: Octave cannot load its default font, so it cannot draw axes " ...
              "(%s); install the Debian package fonts-freefont-otf (make deps does)"],
             fname, err.message);
    endif
    rethrow (err);
  end_try_catch
endfunction
