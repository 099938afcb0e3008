## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{e} =} fit_metrics (@var{f}, @var{y}, @var{cosi}, @var{wt})
## The fit's error measures for one channel (private; the one place
## lafortune_fit computes them).  @var{f} model values, @var{y} data,
## @var{cosi} cos theta_i, @var{wt} sample weights (N x 1 each); each mean
## is weighted by @var{wt}.  Fields: rmse, rel_rmse (rmse / rms of the data),
## log_rmse (log (f + delta) - log (y + delta), delta = fit_log_delta (y, wt)),
## cos_rmse (residual times cos theta_i).
## @end deftypefn
function e = fit_metrics (f, y, cosi, wt)
  W = max (sum (wt), realmin);
  wm = @(v) sqrt (sum (wt .* v .^ 2) / W);
  r = f - y;
  e.rmse = wm (r);
  e.rel_rmse = e.rmse / max (wm (y), realmin);
  if (e.rmse == 0)
    e.rel_rmse = 0;
  endif
  d = fit_log_delta (y, wt);
  e.log_rmse = wm (log (max (f, 0) + d) - log (max (y, 0) + d));
  e.cos_rmse = wm (r .* cosi);
endfunction
