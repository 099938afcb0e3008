## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{a} =} model_albedo (@var{def}, @var{p}, @var{theta})
## The directional albedo of one channel of a physically based model
## (@var{p} as model_core takes it) at the incidence angles @var{theta}
## (radians, a column): a(theta_i) = integral of f (wi, wo) cos theta_o
## over the hemisphere of wo.  The Lambertian term gives rho_d exactly; each
## lobe is integrated over the half vector h (d omega_o = 4 (wi.h) d
## omega_h), with Gauss-Legendre nodes in theta_h on intervals set by the
## lobe's width w (the model's @code{width}): edges at tan theta_h = 2 w,
## 8 w, ..., 8192 w, each 4 times the last, so that the nodes are dense
## where the lobe lives, whatever its roughness, and follow a heavy tail
## (GGX's falls as tan^-4 theta_h) out to the horizon; the midpoint rule in
## phi_h over [0, pi] (the integrand is even in phi_h).
## @end deftypefn

function a = model_albedo (def, p, theta)
  persistent gx gw
  NT = 64;                      # Gauss-Legendre nodes per theta_h interval
  NP = 128;                     # phi_h nodes over [0, pi]
  if (isempty (gx))
    ## Golub-Welsch on [-1, 1]
    b = (1:NT-1) ./ sqrt (4 * (1:NT-1) .^ 2 - 1);
    [V, L] = eig (diag (b, 1) + diag (b, -1));
    [gx, o] = sort (diag (L));
    gw = 2 * V(1,o)' .^ 2;
  endif
  theta = theta(:);
  a = p(1) * ones (numel (theta), 1);
  ns = numel (def.shape);
  nl = (numel (p) - 1) / (1 + ns);
  ph = ((1:NP)' - 0.5) * pi / NP;
  for k = 1:nl
    j0 = 1 + (k-1) * (1 + ns);
    ks = p(j0+1);
    q = p(j0+1+(1:ns));
    if (ks == 0)
      continue;
    endif
    w = def.width (q);
    e = unique ([0, min(atan (2 * 4 .^ (0:6) * w), pi/2), pi/2]);
    th = []; tw = [];
    for i = 1:numel (e) - 1
      th = [th; (e(i) + e(i+1)) / 2 + (e(i+1) - e(i)) / 2 * gx];
      tw = [tw; (e(i+1) - e(i)) / 2 * gw];
    endfor
    [TH, PH] = ndgrid (th, ph);
    W = (tw .* sin (th)) * ones (1, NP) * (2 * pi / NP);    # both halves of phi_h
    h = [sin(TH(:)) .* cos(PH(:)), sin(TH(:)) .* sin(PH(:)), cos(TH(:))];
    for t = 1:numel (theta)
      wi = [sin(theta(t)), 0, cos(theta(t))];
      ih = h * wi.';
      wo = 2 * ih .* h - wi;
      ok = ih > 0 & wo(:,3) > 0 & wi(3) > 0;
      if (! any (ok))
        continue;
      endif
      X = [wi(3) * ones(nnz (ok), 1), wo(ok,3), wo(ok,:) * wi.'];
      g = def.lobe (X, q);
      a(t) += ks * sum (W(ok) .* g .* wo(ok,3) .* 4 .* ih(ok));
    endfor
  endfor
endfunction
