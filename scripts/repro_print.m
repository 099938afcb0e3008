## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_print (@var{h}, @var{file}, @var{dpi}, @var{who})
## Print figure @var{h} of a pipeline step to the PNG @var{file} at
## @var{dpi} through the package's one atomic write
## (@code{__lafortune_write__}), its folder made if needed; the figure is
## closed.  Errors @code{lafortune:unwritable}, naming @var{who}.
## @end deftypefn
function repro_print (h, file, dpi, who)
  repro_mkdir (fileparts (file));
  unwind_protect
    __lafortune_write__ (file, who, "file",
                         @(tmp) print (h, "-dpngcairo", sprintf ("-r%d", dpi), tmp));
  unwind_protect_cleanup
    close (h);
  end_unwind_protect
endfunction
