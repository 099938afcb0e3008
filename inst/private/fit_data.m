## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{D} =} fit_data (@var{x}, @var{y}, @var{wt}, @var{cosi}, @var{weight}, @var{j}, @var{xc})
## One channel's data as the fit sees it (private).  @var{x} = [a, c]
## (N x 2), @var{y} the channel (N x 1), @var{wt} sample weights, @var{cosi}
## cos theta_i, @var{weight} the residual weighting ("plain", "cosine",
## "relative", "log"), @var{j} and @var{xc} a grouping from fit_reduce.
##
## The data are divided by their largest magnitude @code{D.s} first, so
## that nothing in the fit depends on the data's units (map the parameters
## back with fit_unscale).  The objective is sum_i wt_i (w_i (ty_i -
## tf(f_i)))^2 / sum_i wt_i, tf = identity or log; per group it keeps the
## summed squared weights @code{D.w .^ 2}, the weighted mean target
## @code{D.ty} and the within-group remainder @code{D.wsw}, so that a fit over
## the groups has the same objective (exactly, when the groups hold equal
## (a, c)).  @code{D.cnt}, @code{D.ybar} and @code{D.ssw} do the same for the
## plain rmse, @code{D.wl}, @code{D.yl} for the linear amplitudes of the
## candidate starts.
## @end deftypefn
function D = fit_data (x, y, wt, cosi, weight, j, xc)
  s = max (abs (y(wt > 0)));
  if (! (s > 0))
    s = 1;
  endif
  y = y / s;
  dl = 1;
  if (any (strcmp (weight, {"relative", "log"})))
    dl = fit_log_delta (y, wt);
  endif
  switch (weight)
    case {"plain", "log"}
      w2 = ones (size (y));
    case "cosine"
      w2 = cosi .^ 2;
    case "relative"
      w2 = 1 ./ max (y, dl) .^ 2;
  endswitch
  islog = strcmp (weight, "log");
  if (islog)
    ty = log (max (y, 0) + dl);
    wl2 = 1 ./ (max (y, 0) + dl) .^ 2;     # first-order weights for amplitudes
  else
    ty = y;
    wl2 = w2;
  endif
  W = accumarray (j, wt .* w2);
  Wl = accumarray (j, wt .* wl2);
  D.x = xc;
  D.w = sqrt (W);
  D.ty = accumarray (j, wt .* w2 .* ty) ./ max (W, realmin);
  D.wl = sqrt (Wl);
  D.yl = accumarray (j, wt .* wl2 .* y) ./ max (Wl, realmin);
  D.cnt = accumarray (j, wt);
  D.ybar = accumarray (j, wt .* y) ./ max (D.cnt, realmin);
  D.n = max (sum (wt), realmin);
  D.ssw = sum (wt .* (y - D.ybar(j)) .^ 2);
  D.wsw = sum (wt .* w2 .* (ty - D.ty(j)) .^ 2);
  D.s = s;
  D.dl = dl;
  D.islog = islog;
  D.ymax = max (abs (y(wt > 0)));
endfunction
