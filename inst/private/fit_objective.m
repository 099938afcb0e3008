## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{obj}, @var{rmse}] =} fit_objective (@var{D}, @var{F}, @var{Ft})
## The root of the mean merged sum of squares of @var{D} (from fit_data;
## private) for model values @var{F} at its groups: sqrt (ss / norm), the
## value of "plain", "cosine" and the other per-channel metrics.  @var{F}
## may have several columns (one value per column).  @var{rmse}: the plain
## rmse in the data's units, of @code{D.P} (the plain metric's groups) for
## the model values @code{D.s * F}; when @code{D.same} (the fit's metric is
## the plain one), that is @code{D.s * obj}.  @var{Ft}, when given, is
## @var{F} already transformed by the metric (@code{D.t}).
## @end deftypefn
function [obj, rmse] = fit_objective (D, F, Ft)
  if (nargin < 3)
    Ft = F;
    if (! D.identity)
      Ft = D.t (F, D.c);
    endif
  endif
  obj = sqrt ((sum (D.w .^ 2 .* (D.ty - Ft) .^ 2, 1) + D.wsw) / D.n);
  if (nargout > 1)
    if (D.same)
      rmse = D.s * obj;
    else
      rmse = fit_objective (D.P, D.s * F);
    endif
  endif
endfunction
