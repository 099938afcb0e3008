## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_print (@var{h}, @var{file}, @var{dpi}, @var{who})
## Print figure @var{h} of a pipeline step to the PNG @var{file} at
## @var{dpi}, atomically (the scripts' counterpart of the package's private
## plot_save): its folder made if needed, a temporary file beside it checked
## to be non-empty, then renamed; the figure is closed.  Errors
## @code{lafortune:unwritable}, naming @var{who}.
## @end deftypefn
function repro_print (h, file, dpi, who)
  d = fileparts (file);
  repro_mkdir (d);
  tmp = [file ".tmp.png"];
  unwind_protect
    print (h, "-dpngcairo", sprintf ("-r%d", dpi), tmp);
  unwind_protect_cleanup
    close (h);
  end_unwind_protect
  s = dir (tmp);
  if (isempty (s) || s.bytes == 0)
    if (exist (tmp, "file"))
      unlink (tmp);
    endif
    error ("lafortune:unwritable", "%s: printing '%s' gave an empty file (disk full?)", who, file);
  endif
  [err, msg] = rename (tmp, file);
  if (err)
    error ("lafortune:unwritable", "%s: cannot write '%s': %s", who, file, msg);
  endif
endfunction
