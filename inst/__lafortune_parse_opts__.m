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

%!test
%! d = struct ("size", 3, "name", "a");
%! o = __lafortune_parse_opts__ ({"SIZE", 5}, "f", d);
%! assert (o.size, 5);
%! assert (o.name, "a");
%! assert (isequal (__lafortune_parse_opts__ ({}, "f", d), d));
%!error <f: unknown option 'colour'; valid options: size, name> __lafortune_parse_opts__ ({"colour", 1}, "f", struct ("size", 3, "name", "a"))
%!error <f: options must be NAME, VALUE pairs> __lafortune_parse_opts__ ({"size"}, "f", struct ("size", 3))
%!error <f: option names must be strings> __lafortune_parse_opts__ ({3, 1}, "f", struct ("size", 3))
