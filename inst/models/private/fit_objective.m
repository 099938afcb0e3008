## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{obj}, @var{rmse}] =} fit_objective (@var{D}, @var{F}, @var{Ft})
## The root of the mean merged sum of squares of @var{D} (from fit_data or
## fit_stack; private) for model values @var{F} at its groups: sqrt (ss /
## norm), the value of "plain", "cosine" and the other per-channel metrics;
## for several channels (@code{D.nch} > 1, rows channel after channel) ss
## is the sum of the channels'.  @var{F} may have several columns (one
## value per column).  @var{rmse}: the plain rmse in the data's units per
## channel (1 x nch; one column of @var{F}), of @code{D.P} (the plain
## metric's groups) for the model values @code{D.s * F}; when
## @code{D.same} (the fit's metric is the plain one), that is @code{D.s}
## times the channel's objective.  @var{Ft}, when given, is @var{F} already
## transformed by the metric (@code{D.t}).
## @end deftypefn
function [obj, rmse] = fit_objective (D, F, Ft)
  if (nargin < 3)
    Ft = F;
    if (! D.identity)
      Ft = D.t (F, D.c);
    endif
  endif
  ss = sum (D.w .^ 2 .* (D.ty - Ft) .^ 2, 1);
  if (D.nch == 1)
    obj = sqrt ((ss + D.wsw) / D.n);
    if (nargout > 1)
      if (D.same)
        rmse = D.s * obj;
      else
        rmse = fit_objective (D.P, D.s * F);
      endif
    endif
    return;
  endif
  G = rows (D.x);
  R2 = D.w .^ 2 .* (D.ty - Ft) .^ 2;
  ssc = reshape (sum (reshape (R2, G, D.nch, []), 1), D.nch, []);    # nch x columns
  obj = sqrt ((sum (ssc, 1) + sum (D.wsw)) / D.n);
  if (nargout > 1)
    if (D.same)
      rmse = D.s * sqrt ((ssc(:,1).' + D.wsw) / D.n);
    else
      P = D.P;
      P2 = P.w .^ 2 .* (P.ty - D.s * F(:,1)) .^ 2;
      rmse = sqrt ((sum (reshape (P2, G, D.nch), 1) + P.wsw) / P.n);
    endif
  endif
endfunction
