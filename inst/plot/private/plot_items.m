## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{items}, @var{names}] =} plot_items (@var{x}, @var{names}, @var{fname}, @var{what})
## Materials to plot as a cell (private): @var{x} is a Lafortune model, a
## MERL material or a cell of them (empty: none).  @var{names} (cellstr, or
## empty for the defaults) labels them: a model's or material's own
## @code{name}, else "K lobe(s)" for a model and "measured" for MERL data.
## Errors with @code{lafortune:badMaterial} or @code{lafortune:badOption}.
## @end deftypefn
function [items, names] = plot_items (x, names, fname, what)
  if (isempty (x))
    items = {};
  elseif (iscell (x))
    items = x(:).';
  else
    items = {x};
  endif
  for k = 1:numel (items)
    if (isempty (__lafortune_material_kind__ (items{k})))
      error ("lafortune:badMaterial",
             "%s: %s must be analytic models (Lafortune: fields rho_d, Cxy, Cz, e; others: see brdf_model) or MERL materials (fields data, valid); item %d is a %s",
             fname, what, k, class (items{k}));
    endif
  endfor
  if (isempty (names))
    names = cell (1, numel (items));
    for k = 1:numel (items)
      m = items{k};
      if (isfield (m, "name") && ischar (m.name) && ! isempty (m.name))
        names{k} = m.name;
      elseif (strcmp (__lafortune_material_kind__ (m), "lafortune"))
        names{k} = sprintf ("%d lobe(s)", rows (m.Cxy));
      elseif (strcmp (__lafortune_material_kind__ (m), "model"))
        names{k} = sprintf ("%s, %d lobe(s)", m.type, rows (m.ks));
      else
        names{k} = "measured";
      endif
    endfor
  elseif (ischar (names) && numel (items) == 1)
    names = {names};
  elseif (! iscellstr (names) || numel (names) != numel (items))
    error ("lafortune:badOption", "%s: NAMES must be a cell of %d strings, one per %s",
           fname, numel (items), what);
  endif
  names = names(:).';
endfunction
