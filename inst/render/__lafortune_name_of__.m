## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{nm} =} __lafortune_name_of__ (@var{s})
## The field @code{name} of the struct @var{s} when it is a string, else ""
## (private): the name of a material or a scene for headers and tables.
## @end deftypefn
function nm = __lafortune_name_of__ (s)
  nm = "";
  if (isstruct (s) && isfield (s, "name") && ischar (s.name))
    nm = s.name;
  endif
endfunction
