## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{opt} =} __lafortune_parse_opts__ (@var{args}, @var{fname}, @var{defaults})
## Parse name/value pairs in the cell @var{args} against the struct
## @var{defaults} (private).  Names are case-insensitive; an unknown name or
## an odd count gives @code{lafortune:badOption} naming the valid ones.
## @end deftypefn
function opt = __lafortune_parse_opts__ (args, fname, defaults)
  opt = defaults;
  names = fieldnames (defaults);
  if (mod (numel (args), 2) != 0)
    error ("lafortune:badOption", "%s: options must be NAME, VALUE pairs", fname);
  endif
  for k = 1:2:numel (args)
    nm = args{k};
    if (! ischar (nm))
      error ("lafortune:badOption", "%s: option names must be strings", fname);
    endif
    i = find (strcmpi (nm, names), 1);
    if (isempty (i))
      error ("lafortune:badOption", "%s: unknown option '%s'; valid options: %s",
             fname, nm, strjoin (names', ", "));
    endif
    opt.(names{i}) = args{k+1};
  endfor
endfunction
