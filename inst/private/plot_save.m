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
  tmp = atomic_tmp (file, fname);
  device = "-dpng";
  if (strcmp (get (hf, "__graphics_toolkit__"), "gnuplot"))
    device = "-dpngcairo";
  endif
  try
    print (hf, device, "-r90", tmp);
  catch err
    unlink (tmp);
    error ("lafortune:unwritable", "%s: cannot print the figure to '%s': %s",
           fname, file, err.message);
  end_try_catch
  s = dir (tmp);
  if (isempty (s) || s.bytes == 0)
    unlink (tmp);
    error ("lafortune:unwritable", "%s: printing the figure to '%s' gave an empty file",
           fname, file);
  endif
  atomic_commit (tmp, file, fname);
endfunction
