## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{f}, @var{J}] =} lafortune_core (@var{p}, @var{sxy}, @var{sz})
## The one evaluation of the isotropic Lafortune model for one channel (private).
##
## @var{p} = [rho_d; Cxy_1; Cz_1; e_1; Cxy_2; ...] (column), @var{sxy} =
## ux vx + uy vy and @var{sz} = uz vz (column vectors).  Returns
## f = rho_d/pi + sum_k max (Cxy_k sxy + Cz_k sz, 0)^e_k and, on request, the
## Jacobian df/dp (N x numel(p)).  Lobe bases are clamped at 0 and powers are
## taken in log space with the exponent of each lobe capped at LOGMAX = 300
## (a lobe never exceeds exp(300)), so the result is real and finite for any
## finite input.  lafortune_eval, lafortune_fit, the exports and both
## renderers go through this function.
## @end deftypefn
function [f, J] = lafortune_core (p, sxy, sz)
  LOGMAX = 300;
  n = numel (sxy);
  nl = (numel (p) - 1) / 3;
  f = zeros (n, 1) + p(1) / pi;
  if (nargout > 1)
    J = zeros (n, numel (p));
    J(:,1) = 1 / pi;
  endif
  for k = 1:nl
    cxy = p(3*k-1);
    cz = p(3*k);
    e = p(3*k+1);
    b = cxy * sxy + cz * sz;
    on = b > 0;
    ## log of the clamped base; realmin keeps it finite, ON zeroes the lobe
    lb = log (max (b, realmin));
    if (e == 0)
      L = double (on);
    else
      t = e * lb;
      L = exp (max (min (t, LOGMAX), -700)) .* on;   # no denormals: they are slow
    endif
    f += L;
    if (nargout > 1)
      if (e == 0)
        dLdb = zeros (n, 1);
        dLde = lb .* on;
      else
        ## d/db of b^e = e b^(e-1), formed in log space; 0 where capped
        live = on & (t <= LOGMAX);
        dLdb = e * exp (max (min (t - lb, LOGMAX), -700)) .* live;
        dLde = L .* lb .* live;
      endif
      J(:,3*k-1) = dLdb .* sxy;
      J(:,3*k)   = dLdb .* sz;
      J(:,3*k+1) = dLde;
    endif
  endfor
endfunction
