## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} fit_starts (@var{D}, @var{p}, @var{refine})
## Candidate starts for one more lobe on top of parameters @var{p}
## (private).  Each candidate lobe (forward lobes from steep to flat,
## retro-reflective, near-normal directions; exponents 1 to 1e5, two per
## decade) gets its best non-negative amplitude, together with a change of
## rho_d, by linear least squares against the residual of @var{p} on @var{D}
## (from fit_data); a lobe that is non-negligible on fewer than 0.2% of the
## groups (at least 8) is skipped.  @var{P} holds, as
## columns, the best start of each direction family, best family first.
##
## With @var{refine} true, the best start is then refined the same way on a
## finer grid around it: 9 directions within 0.35 rad of its own and 9
## exponents within half a decade, 8 per decade.  A start that no warm-up
## run brings closer (fit_channel) needs that: on the in-plane tables of
## both paper materials the first lobe's Levenberg-Marquardt run then takes
## 4 to 6 iterations per channel instead of 8 to 10, to the same minimum.
## @end deftypefn
function P = fit_starts (D, p, refine = false)
  ## directions (Cxy, Cz) of the families: forward lobes from steep to flat,
  ## retro-reflective, near-normal
  dirs = [-1 1; -1 0.7; -1 1.3; -1 0.4; -1 0.2; -1 2; 1 1; 0 1];
  expo = 10 .^ (0:0.5:5);
  fcur = lafortune_core (p, D.x(:,1), D.x(:,2));
  ## every candidate at once, one column each (family by family, each
  ## with every exponent)
  nd = rows (dirs);
  ne = numel (expo);
  fam = ceil ((1:nd*ne) / ne);
  ex = expo(mod (0:nd*ne-1, ne) + 1);
  C = score (D, p, fcur, dirs, fam, ex);
  if (isempty (C.obj))
    P = zeros (numel (p) + 3, 0);
    return;
  endif
  [~, order] = sort (C.obj);
  ## the best of each family, best family first
  [~, first] = unique (fam(C.k(order)), "first");
  best = order(sort (first));
  P = starts (p, C, best);
  if (refine)
    b = C.k(best(1));
    phi = atan2 (dirs(fam(b),2), dirs(fam(b),1)) + linspace (-0.35, 0.35, 9);
    [ph, er] = meshgrid (phi, ex(b) * 10 .^ (-0.5:0.125:0.5));
    F = score (D, p, fcur, [cos(ph(:)) sin(ph(:))], 1:numel (ph), er(:).');
    [o, i] = min (F.obj);
    if (o < C.obj(best(1)))
      P(:,1) = starts (p, F, i);
    endif
  endif
endfunction

## The candidate lobes of directions DIRS(FAM,:) and exponents EX on top of
## P (model values FCUR), each with its amplitude and change of rho_d/pi:
## C.k the usable candidates, C.obj their objectives, C.a, C.d, C.dir, C.e
## their parameters
function C = score (D, p, fcur, dirs, fam, ex)
  m = rows (D.x);
  min_support = min (max (8, 0.002 * m), m);
  r = D.yl - fcur;
  wl2 = D.wl .^ 2;
  S1 = sum (wl2);
  Sr = sum (wl2 .* r);
  ## g = b^e where the base b > 0, else 0
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
  C.k = find (ok);
  C.obj = fit_objective (D, fcur + d(ok) + g(:,ok) .* s(ok));
  C.a = a(ok);
  C.d = d(ok);
  C.dir = dirs(fam(ok),:);
  C.e = ex(ok);
endfunction

## The starts of the candidates I of C (columns) on top of P
function P = starts (p, C, i)
  P = [p(:,ones (1, numel (i))); C.a(i) .* C.dir(i,:).'; C.e(i)];
  P(1,:) = max (p(1) + pi * C.d(i), 0);
endfunction
