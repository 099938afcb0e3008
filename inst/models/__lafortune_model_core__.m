## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {[@var{f}, @var{J}] =} __lafortune_model_core__ (@var{def}, @var{p}, @var{X})
## One channel of a physically based model (@code{model_def}) at @var{X} =
## [cos theta_i, cos theta_o, wi.wo] (N x 3, both cosines > 0): @var{p} =
## [rho_d; ks_1; q_1; ks_2; q_2; ...] in the model's own units, f = rho_d /
## pi + sum_k ks_k g (X, q_k), and @var{J} = df/dp (N x numel (p)).  The
## one evaluation of these models: material_eval, the fit and the exports'
## checks go through it (the albedo's quadrature and the fit's screen of
## starts take the type's lobe g itself, of unit amplitude).
## @end deftypefn

function [f, J] = __lafortune_model_core__ (def, p, X)
  n = rows (X);
  m = 1 + numel (def.shape);
  nl = (numel (p) - 1) / m;
  f = zeros (n, 1) + p(1) / pi;
  jac = nargout > 1;
  if (jac)
    J = zeros (n, numel (p));
    J(:,1) = 1 / pi;
  endif
  for k = 1:nl
    i = 1 + (k-1) * m;
    ks = p(i+1);
    q = p(i+2:i+m);
    if (jac)
      [g, dg] = def.lobe (X, q);
      J(:,i+1) = g;
      J(:,i+2:i+m) = ks * dg;
    else
      if (ks == 0)
        continue;
      endif
      g = def.lobe (X, q);
    endif
    f += ks * g;
  endfor
endfunction
