## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {[@var{model}, @var{def}] =} __lafortune_check_model__ (@var{model}, @var{fname})
## @deftypefnx {} {[@var{model}, @var{def}] =} __lafortune_check_model__ (@var{model}, @var{fname}, "lafortune")
## Validate an analytic model struct (private), of any type of
## @code{model_def}, and return it with its parameters as doubles and its
## type's definition @var{def}.  A struct without @code{type} is a Lafortune
## model.  The fields are those of @code{def.fields}: @code{rho_d} (1 x 3)
## and the others NLOBES x 3 (NLOBES 0..8), real and finite, within the
## type's bounds (Lafortune: e >= 0, rho_d >= 0).  With "lafortune", any
## other type is an error too.  Error ids @code{lafortune:badModel},
## @code{lafortune:badModelType}.
## @end deftypefn
function [model, def] = __lafortune_check_model__ (model, fname, only)
  if (! isstruct (model) || ! isscalar (model))
    error ("lafortune:badModel",
           "%s: MODEL must be a scalar struct (a Lafortune model has fields rho_d, Cxy, Cz, e; other types a field type), got %s",
           fname, class (model));
  endif
  type = "lafortune";
  if (isfield (model, "type"))
    type = model.type;
    if (! ischar (type) || ! any (strcmp (type, __lafortune_model_def__ ())))
      error ("lafortune:badModelType", "%s: MODEL.type '%s' is not a model type; expected one of %s",
             fname, __lafortune_arg_str__ (type), strjoin (__lafortune_model_def__ (), ", "));
    endif
  endif
  if (nargin > 2 && ! strcmp (type, only))
    error ("lafortune:badModelType", "%s: MODEL must be a %s model, got type '%s'",
           fname, only, type);
  endif
  def = __lafortune_model_def__ (type);
  req = def.fields;
  for k = 1:numel (req)
    if (! isfield (model, req{k}))
      error ("lafortune:badModel", "%s: MODEL has no field '%s' (a %s model needs %s)",
             fname, req{k}, type, strjoin (req, ", "));
    endif
    v = model.(req{k});
    if (! (isnumeric (v) && isreal (v)) || ! all (isfinite (v(:))))
      error ("lafortune:badModel", "%s: MODEL.%s must be real, finite and numeric",
             fname, req{k});
    endif
    model.(req{k}) = double (v);
  endfor
  if (! isequal (size (model.rho_d), [1 3]))
    error ("lafortune:badModel", "%s: MODEL.rho_d must be 1 x 3 (R, G, B), got %s",
           fname, mat2str (size (model.rho_d)));
  endif
  f1 = req{2};
  if (! isempty (model.(f1)) && columns (model.(f1)) != 3)
    error ("lafortune:badModel",
           "%s: MODEL.%s must be NLOBES x 3 (one column per channel R, G, B), got %s",
           fname, f1, mat2str (size (model.(f1))));
  endif
  n = rows (model.(f1));
  if (all (cellfun (@(f) isempty (model.(f)), req(2:end))))
    for f = req(2:end)
      model.(f{1}) = zeros (0, 3);
    endfor
    n = 0;
  endif
  for f = req(3:end)
    if (! isequal (size (model.(f{1})), [n 3]))
      error ("lafortune:badModel",
             "%s: MODEL.%s must be NLOBES x 3 like MODEL.%s (%d x 3), got %s",
             fname, f{1}, f1, n, mat2str (size (model.(f{1}))));
    endif
  endfor
  if (n > 8)
    error ("lafortune:badModel", "%s: MODEL has %d lobes, expected at most 8", fname, n);
  endif
  if (any (model.rho_d < 0))
    error ("lafortune:badModel", "%s: MODEL.rho_d must be >= 0", fname);
  endif
  if (isempty (def.lobe))
    if (any (model.e(:) < 0))
      error ("lafortune:badModel", "%s: MODEL.e must be >= 0", fname);
    endif
    return;
  endif
  for j = 1:numel (req) - 1
    v = model.(req{j+1});
    if (any (v(:) < def.lo(j)) || any (v(:) > def.hi(j)))
      error ("lafortune:badModel", "%s: MODEL.%s must be in [%g, %g] (a %s model), got %s",
             fname, req{j+1}, def.lo(j), def.hi(j), type, mat2str (v, 4));
    endif
  endfor
endfunction
