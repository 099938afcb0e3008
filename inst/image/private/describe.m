## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{s} =} describe (@var{x})
## What a value is, for an error message that says what it got (private):
## its size and class for an array (@qcode{"4x4x2 complex double"}), its
## class otherwise.
## @end deftypefn
function s = describe (x)
  if (! (isnumeric (x) || islogical (x) || ischar (x)))
    s = class (x);
    return;
  endif
  cplx = "";
  if (isnumeric (x) && ! isreal (x))
    cplx = "complex ";
  endif
  s = sprintf ("%s %s%s", strjoin (arrayfun (@num2str, size (x), "uniformoutput", false), "x"),
               cplx, class (x));
endfunction
