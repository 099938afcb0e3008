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

%!assert (__lafortune_arg_str__ ("ggx"), "ggx")
%!assert (__lafortune_arg_str__ (3), "double")
%!assert (__lafortune_arg_str__ ({1}), "cell")
%!assert (__lafortune_arg_str__ (struct ()), "struct")
