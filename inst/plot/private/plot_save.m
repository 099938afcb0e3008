## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} plot_save (@var{hf}, @var{file}, @var{fname})
## Print figure @var{hf} to the PNG @var{file} (private), atomically: into a
## temporary file in the same folder, checked to be non-empty, then renamed.
## The gnuplot toolkit prints with @code{-dpngcairo}, the others with
## @code{-dpng}; at 90 dpi the PNG has the figure's size in pixels.  Nothing
## is done when @var{file} is empty.
## @end deftypefn
function plot_save (hf, file, fname)
  if (isempty (file))
    return;
  endif
  if (! ischar (file) || rows (file) != 1)
    error ("lafortune:badFile", "%s: FILE must be a file name (a string), got %s",
           fname, class (file));
  endif
  [~, ~, ext] = fileparts (file);
  if (! strcmpi (ext, ".png"))
    error ("lafortune:badFile", "%s: FILE must end in .png, got '%s'", fname, file);
  endif
  device = "-dpng";
  if (strcmp (get (hf, "__graphics_toolkit__"), "gnuplot"))
    device = "-dpngcairo";
  endif
  __lafortune_write__ (file, fname, "file", @(tmp) print (hf, device, "-r90", tmp));
endfunction
