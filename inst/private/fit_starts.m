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
  ## every candidate at once, one column each (family by family, each
  ## with every exponent): g = b^e where the base b > 0, else 0
  nd = rows (dirs);
  ne = numel (expo);
  fam = ceil ((1:nd*ne) / ne);
  ex = expo(mod (0:nd*ne-1, ne) + 1);
  B = D.x * dirs.';
  on = double (B > 0);
  lb = log (max (B, realmin));
  g = exp (max (lb(:,fam) .* ex, -700)) .* on(:,fam);
  ## amplitude s >= 0 and a change d of rho_d/pi (rho_d stays >= 0) by
  ## linear least squares
  Sg = wl2.' * g;
  Sgg = wl2.' * g .^ 2;
  Sgr = (wl2 .* r).' * g;
  dt = S1 * Sgg - Sg .^ 2;
  s = (S1 * Sgr - Sg * Sr) ./ dt;
  d = (Sr - s .* Sg) / S1;
  alone = ! (dt > 0 & s > 0 & d >= -p(1) / pi);
  s(alone) = Sgr(alone) ./ Sgg(alone);
  d(alone) = 0;
  a = s .^ (1 ./ ex);
  ## a lobe that lives on a handful of samples is no start
  support = sum (g > 1e-3 * max (g, [], 1), 1);
  ok = Sgg > 0 & s > 0 & isfinite (a) & a > 0 & support >= min_support;
  if (! any (ok))
    P = zeros (numel (p) + 3, 0);
    return;
  endif
  ## the objective of every candidate
  obj = fit_objective (D, fcur + d(ok) + g(:,ok) .* s(ok));
  k = find (ok);
  [~, order] = sort (obj);
  ## the best of each family, best family first
  [~, first] = unique (fam(k(order)), "first");
  best = k(order(sort (first)));
  P = [p(:,ones (1, numel (best))); a(best) .* dirs(fam(best),:).'; ex(best)];
  P(1,:) = max (p(1) + pi * d(best), 0);
endfunction
