## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{model} =} check_model (@var{model}, @var{fname})
## Validate a Lafortune model struct (private): fields @code{rho_d} (1 x 3),
## @code{Cxy}, @code{Cz}, @code{e} (nlobes x 3, nlobes 0..8), all real and
## finite, @code{e >= 0}.  Error id @code{lafortune:badModel}.
## @end deftypefn
function model = check_model (model, fname)
  if (! isstruct (model) || ! isscalar (model))
    error ("lafortune:badModel",
           "%s: MODEL must be a scalar struct with fields rho_d, Cxy, Cz, e, got %s",
           fname, class (model));
  endif
  req = {"rho_d", "Cxy", "Cz", "e"};
  for k = 1:numel (req)
    if (! isfield (model, req{k}))
      error ("lafortune:badModel", "%s: MODEL has no field '%s' (needs rho_d, Cxy, Cz, e)",
             fname, req{k});
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
  if (! isempty (model.Cxy) && columns (model.Cxy) != 3)
    error ("lafortune:badModel",
           "%s: MODEL.Cxy must be NLOBES x 3 (one column per channel R, G, B), got %s",
           fname, mat2str (size (model.Cxy)));
  endif
  n = rows (model.Cxy);
  if (isempty (model.Cxy) && isempty (model.Cz) && isempty (model.e))
    model.Cxy = model.Cz = model.e = zeros (0, 3);
    n = 0;
  endif
  for f = {"Cxy", "Cz", "e"}
    if (! isequal (size (model.(f{1})), [n 3]))
      error ("lafortune:badModel",
             "%s: MODEL.%s must be NLOBES x 3 like MODEL.Cxy (%d x 3), got %s",
             fname, f{1}, n, mat2str (size (model.(f{1}))));
    endif
  endfor
  if (n > 8)
    error ("lafortune:badModel", "%s: MODEL has %d lobes, expected at most 8", fname, n);
  endif
  if (any (model.e(:) < 0))
    error ("lafortune:badModel", "%s: MODEL.e must be >= 0", fname);
  endif
  if (any (model.rho_d < 0))
    error ("lafortune:badModel", "%s: MODEL.rho_d must be >= 0", fname);
  endif
endfunction
