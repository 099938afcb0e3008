## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{f}, @var{J}] =} fit_eval (@var{D}, @var{p})
## The model's values (and Jacobian) at the groups of the fit's data @var{D}
## (private), in its type's fit coordinates @code{D.def.coords}: for
## Lafortune (brdf_lafortune) one channel's parameters, or lobes shared
## across the channels when @code{D.nch} > 1 (fit_stack), channel after
## channel; for a physically based type @code{fit_phys}.
## @end deftypefn
function [f, J] = fit_eval (D, p)
  if (nargout > 1)
    [f, J] = D.def.coords ("eval", D, p);
  else
    f = D.def.coords ("eval", D, p);
  endif
endfunction
