## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{lp} =} __lafortune_log_peaks__ (@var{cxy}, @var{cz}, @var{e})
## The log of each Lafortune lobe's largest value on the hemisphere,
## max (Cz, |Cxy|, 0)^e, element by element (internal): -Inf for a lobe
## that is zero everywhere, 0 for a step (e = 0) that is somewhere on, Inf
## for a lobe with a field that is not finite or e < 0.  The one definition
## for the fit's guard (fit_guard) and the check of models
## (__lafortune_check_bounded__).
##
## @example
## __lafortune_log_peaks__ (-1.2, 1, 10)      # 10 log (1.2)
## @end example
## @end deftypefn
function lp = __lafortune_log_peaks__ (cxy, cz, e)
  b = max (max (cz, abs (cxy)), 0);
  lp = e .* log (b);
  lp(e == 0 & b > 0) = 0;
  lp(b == 0) = -Inf;
  lp(! isfinite (cxy) | ! isfinite (cz) | ! isfinite (e) | e < 0) = Inf;
endfunction

%!assert (__lafortune_log_peaks__ ([-1.2 0.5 0 2], [1 0.9 0 -1], [10 2 3 0]), [10*log(1.2) 2*log(0.9) -Inf 0], 1e-14)
%!assert (__lafortune_log_peaks__ ([NaN 1], [1 1], [1 -1]), [Inf Inf])
