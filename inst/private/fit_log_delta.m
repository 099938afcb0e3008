## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} fit_log_delta (@var{y}, @var{wt})
## The offset delta of the "log" and "relative" weightings (private): 0.01
## times the median of the positive data (weighted by @var{wt}, N x 1,
## when given), 1 when there are none.  It scales with the data, so the
## weightings do not depend on the data's units.
## @end deftypefn
function d = fit_log_delta (y, wt = [])
  if (isempty (wt))
    wt = ones (size (y));
  endif
  k = y > 0 & wt > 0;
  if (! any (k))
    d = 1;
    return;
  endif
  if (all (wt(k) == wt(find (k, 1))))
    d = 0.01 * median (y(k));        # equal weights: the plain median
    return;
  endif
  [yp, o] = sort (y(k));
  c = cumsum (wt(k)(o));
  ## the weighted median (the plain median for equal weights)
  h = c(end) / 2;
  i = find (c >= h, 1);
  if (c(i) == h && i < numel (yp))
    d = 0.01 * (yp(i) + yp(i+1)) / 2;
  else
    d = 0.01 * yp(i);
  endif
endfunction
