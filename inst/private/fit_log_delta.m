## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{d} =} fit_log_delta (@var{y})
## The offset delta of the "log" and "relative" weightings (private): 0.01
## times the median of the positive data, 1 when there are none.  It scales
## with the data, so the weightings do not depend on the data's units.
## @end deftypefn
function d = fit_log_delta (y)
  yp = y(y > 0);
  if (isempty (yp))
    d = 1;
  else
    d = 0.01 * median (yp);
  endif
endfunction
