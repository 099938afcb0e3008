## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{f}, @var{J}] =} fit_eval (@var{D}, @var{p})
## The model's values (and Jacobian) at the groups of the fit's data @var{D}
## (private): one channel's Lafortune parameters (lafortune_core), or, when
## @code{D.nch} > 1 (fit_stack), lobes shared across the channels
## (shared_lobes, reference channel @code{D.ref}), channel after channel;
## with @code{D.def}, a physically based model's fit coordinates
## (@code{fit_phys}).
## @end deftypefn
function [f, J] = fit_eval (D, p)
  if (isfield (D, "def"))
    if (nargout > 1)
      [f, J] = fit_phys ("eval", D, p);
    else
      f = fit_phys ("eval", D, p);
    endif
  elseif (D.nch == 1)
    if (nargout > 1)
      [f, J] = __lafortune_lafortune_core__ (p, D.x(:,1), D.x(:,2));
    else
      f = __lafortune_lafortune_core__ (p, D.x(:,1), D.x(:,2));
    endif
  elseif (nargout > 1)
    [f, J] = shared_lobes ("eval", p, D.ref, D.nch, D.x(:,1), D.x(:,2));
  else
    f = shared_lobes ("eval", p, D.ref, D.nch, D.x(:,1), D.x(:,2));
  endif
endfunction
