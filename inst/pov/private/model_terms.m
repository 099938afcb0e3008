## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {[@var{terms}, @var{names}] =} model_terms (@var{model}, @var{fname})
## An analytic model of any type (checked) as the sum of its terms: the
## Lambertian term (when rho_d is not 0) and each lobe, each a model of the
## same type (cells @var{terms}), with @var{names} "diffuse", "lobe 1",
## ...  pov_write_scene tabulates each term on its own.
## @end deftypefn

function [terms, names] = model_terms (model, fname)
  [m, def] = __lafortune_check_model__ (model, fname);
  f = def.fields;
  base = struct ();
  if (! isempty (def.lobe))
    base.type = def.type;
  endif
  base.rho_d = [0 0 0];
  for j = 2:numel (f)
    base.(f{j}) = zeros (0, 3);
  endfor
  terms = {};
  names = {};
  if (any (m.rho_d != 0))
    terms{end+1} = base;
    terms{end}.rho_d = m.rho_d;
    names{end+1} = "diffuse";
  endif
  for k = 1:rows (m.(f{2}))
    t = base;
    for j = 2:numel (f)
      t.(f{j}) = m.(f{j})(k,:);
    endfor
    terms{end+1} = t;
    names{end+1} = sprintf ("lobe %d", k);
  endfor
endfunction
