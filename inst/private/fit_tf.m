## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{t} =} fit_tf (@var{D}, @var{f})
## The transform of model values that the objective compares with
## @code{D.ty} (private): log (max (f, 0) + delta) for the "log" weighting,
## else f itself.
## @end deftypefn
function t = fit_tf (D, f)
  if (D.islog)
    t = log (max (f, 0) + D.dl);
  else
    t = f;
  endif
endfunction
