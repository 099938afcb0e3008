## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} fit_unscale (@var{p}, @var{s})
## Parameters fitted to data divided by @var{s} mapped back to the data's
## units (private): rho_d times @var{s}, each lobe's Cxy and Cz times
## @var{s}^(1/e), so that the model is @var{s} times the fitted one.  A lobe
## with e = 0 (a step) cannot be scaled and is left as it is.
## @end deftypefn
function p = fit_unscale (p, s)
  if (s == 1)
    return;
  endif
  p(1) *= s;
  for k = 1:(numel (p) - 1) / 3
    e = p(3*k+1);
    f = exp (log (s) / e);
    if (e > 0 && isfinite (f) && f > 0)
      p(3*k-1:3*k) *= f;
    endif
  endfor
endfunction
