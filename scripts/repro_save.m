## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_save (@var{file}, @var{value})
## Write @var{value} as JSON (a struct) or as text (a char) to @var{file},
## its folder made if needed, through the package's one atomic write
## (@code{__lafortune_write__}), so that an interrupted step leaves no half
## file for Make to take as done.
## @end deftypefn
function repro_save (file, value)
  repro_mkdir (fileparts (file));
  if (ischar (value))
    txt = value;
  else
    txt = jsonencode (value);
  endif
  __lafortune_write__ (file, "repro_save", "text", txt);
endfunction
