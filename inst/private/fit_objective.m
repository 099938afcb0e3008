## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{obj} =} fit_objective (@var{D}, @var{F})
## The root of the mean merged sum of squares of @var{D} (from fit_data;
## private) for model values @var{F} at its groups: sqrt (ss / norm), the
## value of "plain", "cosine" and the other per-channel metrics.  @var{F}
## may have several columns (one value per column).
## @end deftypefn
function obj = fit_objective (D, F)
  if (! D.identity)
    F = D.t (F, D.c);
  endif
  obj = sqrt ((sum (D.w .^ 2 .* (D.ty - F) .^ 2, 1) + D.wsw) / D.n);
endfunction
