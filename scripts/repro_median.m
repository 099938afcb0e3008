## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{m} =} repro_median (@var{x})
## The median of the finite values of @var{x}, NaN when there are none
## (db_models' medians, bench_sampling's ratios).
## @end deftypefn
function m = repro_median (x)
  x = x(isfinite (x));
  m = NaN;
  if (! isempty (x))
    m = median (x);
  endif
endfunction
