## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## The specs of the reported metrics on the table S (data units): plain,
## log, cosine (unless S.weight already is Ngan's cosine measure) and the
## fit's own; NAMES lists them.  Delta is computed once.
function [rep, names] = fit_specs (S, weight)
  rep.plain = metric_spec ("plain", S, "lafortune_fit");
  names = {"plain", "log", weight};
  if (! (isfield (S, "measure") && strcmp (S.measure, "cosine")))
    names{end+1} = "cosine";
  endif
  names = unique (names);
  for i = 1:numel (names)
    if (! isfield (rep, names{i}))
      rep.(names{i}) = metric_spec (names{i}, S, "lafortune_fit", rep.plain.delta);
    endif
  endfor
endfunction
