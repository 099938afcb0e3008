## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{kind} =} __lafortune_material_kind__ (@var{material})
## "lafortune" (a struct with Cxy and no type, or type "lafortune"),
## "model" (another analytic type, see @code{model_def}), "merl" or "" for
## anything else (private).
## @end deftypefn
function kind = __lafortune_material_kind__ (material)
  kind = "";
  if (isstruct (material) && isscalar (material))
    if (isfield (material, "type"))
      kind = "model";
      if (ischar (material.type) && strcmp (material.type, "lafortune"))
        kind = "lafortune";
      endif
    elseif (isfield (material, "Cxy"))
      kind = "lafortune";
    elseif (isfield (material, "data") && isfield (material, "valid"))
      kind = "merl";
    endif
  endif
endfunction
