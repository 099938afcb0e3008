## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} fit_starts (@var{D}, @var{p})
## Candidate starts for one more lobe on top of parameters @var{p}
## (private).  Each candidate lobe (forward lobes from steep to flat,
## retro-reflective, near-normal directions; exponents 1 to 1e5, two per
## decade) gets its best non-negative amplitude, together with a change of
## rho_d, by linear least squares against the residual of @var{p} on @var{D}
## (from fit_data); a lobe that is non-negligible on fewer than 0.2% of the
## groups (at least 8) is skipped.  @var{P} holds, as
## columns, the best start of each direction family, best family first.
## @end deftypefn
function P = fit_starts (D, p)
  ## directions (Cxy, Cz) of the families: forward lobes from steep to flat,
  ## retro-reflective, near-normal
  dirs = [-1 1; -1 0.7; -1 1.3; -1 0.4; -1 0.2; -1 2; 1 1; 0 1];
  expo = 10 .^ (0:0.5:5);
  m = rows (D.x);
  min_support = min (max (8, 0.002 * m), m);
  fcur = lafortune_core (p, D.x(:,1), D.x(:,2));
  r = D.yl - fcur;
  wl2 = D.wl .^ 2;
  S1 = sum (wl2);
  Sr = sum (wl2 .* r);
  cand = zeros (0, 6);     # [objective, d, cxy, cz, e, family]
  for i = 1:rows (dirs)
    b = dirs(i,1) * D.x(:,1) + dirs(i,2) * D.x(:,2);
    on = find (b > 0);
    if (isempty (on))
      continue;
    endif
    ## every exponent at once: g(:,k) = b^expo(k) where b > 0
    g = exp (max (log (b(on)) * expo, -700));
    ## amplitude s >= 0 and a change d of rho_d/pi (rho_d stays >= 0) by
    ## linear least squares
    Sg = wl2(on).' * g;
    Sgg = wl2(on).' * g .^ 2;
    Sgr = (wl2(on) .* r(on)).' * g;
    dt = S1 * Sgg - Sg .^ 2;
    s = (S1 * Sgr - Sg * Sr) ./ dt;
    d = (Sr - s .* Sg) / S1;
    alone = ! (dt > 0 & s > 0 & d >= -p(1) / pi);
    s(alone) = Sgr(alone) ./ Sgg(alone);
    d(alone) = 0;
    a = s .^ (1 ./ expo);
    ## a lobe that lives on a handful of samples is no start
    support = sum (g > 1e-3 * max (g, [], 1), 1);
    ok = Sgg > 0 & s > 0 & isfinite (a) & a > 0 & support >= min_support;
    if (! any (ok))
      continue;
    endif
    ## the objective of every candidate at once (by columns)
    s = s(ok); d = d(ok); g = g(:,ok);
    F = fcur + d;
    F(on,:) += g .* s;
    obj = fit_objective (D, F);
    cand = [cand; obj(:), d(:), a(ok)(:) * dirs(i,:), expo(ok)(:), i * ones(numel (s), 1)];
  endfor
  if (isempty (cand))
    P = zeros (numel (p) + 3, 0);
    return;
  endif
  [~, order] = sort (cand(:,1));
  [~, first] = unique (cand(order,6), "first");
  order = order(sort (first));
  P = [p(:,ones (1, numel (order))); cand(order,3:5).'];
  P(1,:) = max (p(1) + pi * cand(order,2).', 0);
endfunction
