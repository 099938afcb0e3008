## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{obj}, @var{err}] =} fit_objective (@var{D}, @var{f})
## The fit's own objective (root of the weighted mean square, in the units
## of the scaled data) and the plain rmse in the data's units, for model
## values @var{f} at the groups of @var{D} (from fit_data; private).
## @end deftypefn
function [obj, err] = fit_objective (D, f)
  obj = sqrt ((sum ((D.w .* (D.ty - fit_tf (D, f))) .^ 2) + D.wsw) / D.n);
  if (nargout > 1)
    err = D.s * sqrt ((sum (D.cnt .* (D.ybar - f) .^ 2) + D.ssw) / D.n);
  endif
endfunction
