## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{s} =} __lafortune_arg_str__ (@var{x})
## @var{x} itself when it is a string, else its class (private): for error
## messages that quote what the caller gave.
## @end deftypefn
function s = __lafortune_arg_str__ (x)
  if (ischar (x))
    s = x;
  else
    s = class (x);
  endif
endfunction
