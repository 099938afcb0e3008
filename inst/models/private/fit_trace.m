## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## [seconds, rmse of the best parameters so far (best in the fit's own
## objective)] from rows [seconds, objective, rmse]; when the groups are grid
## cells (EXACT false), a last row holds the fit's rmse on all samples
function T = fit_trace (R, t, err, exact)
  if (isempty (R))
    T = [t, err];
    return;
  endif
  [~, best] = cummin (R(:,2));
  T = [R(:,1), R(best,3)];
  if (! exact)
    T(end+1,:) = [max(t, T(end,1)), err];
  endif
endfunction
