## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} fit_starts (@var{D}, @var{p}, @var{refine})
## Candidate starts for one more lobe on top of parameters @var{p}
## (private; one channel, or several with shared lobes, D.nch > 1).  Each
## candidate lobe (forward lobes from steep to flat,
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
## run brings closer (fit_grow) needs that: the first lobe's
## Levenberg-Marquardt run then takes fewer iterations to the same minimum
## (README, "Measurements behind the design").
## @end deftypefn
function P = fit_starts (D, p, refine = false)
  ## directions (Cxy, Cz) of the families: forward lobes from steep to flat,
  ## retro-reflective, near-normal
  dirs = D.def.starts.dirs;               # (brdf_lafortune)
  expo = D.def.starts.expo;
  fcur = fit_eval (D, p);
  ## every candidate at once, one column each (family by family, each
  ## with every exponent)
  nd = rows (dirs);
  ne = numel (expo);
  fam = ceil ((1:nd*ne) / ne);
  ex = expo(mod (0:nd*ne-1, ne) + 1);
  C = score (D, p, fcur, dirs, fam, ex);
  if (isempty (C.obj))
    P = zeros (numel (p) + 2 + D.nch, 0);
    return;
  endif
  [~, order] = sort (C.obj);
  ## the best of each family, best family first
  [~, first] = unique (fam(C.k(order)), "first");
  best = order(sort (first));
  P = starts (p, C, best, D);
  if (refine)
    b = C.k(best(1));
    phi = atan2 (dirs(fam(b),2), dirs(fam(b),1)) + linspace (-0.35, 0.35, 9);
    [ph, er] = meshgrid (phi, ex(b) * 10 .^ (-0.5:0.125:0.5));
    F = score (D, p, fcur, [cos(ph(:)) sin(ph(:))], 1:numel (ph), er(:).');
    [o, i] = min (F.obj);
    if (o < C.obj(best(1)))
      P(:,1) = starts (p, F, i, D);
    endif
  endif
endfunction

## The candidate lobes of directions DIRS(FAM,:) and exponents EX on top of
## P (model values FCUR), each with its amplitude and change of rho_d/pi per
## channel: C.k the usable candidates, C.obj their objectives, C.a, C.d,
## C.dir, C.e their parameters (C.a and C.d one row per channel).  With
## shared lobes (D.nch > 1) a candidate is usable when the reference
## channel's amplitude is positive; another channel's may be 0
function C = score (D, p, fcur, dirs, fam, ex)
  m = rows (D.x);
  nch = D.nch;
  min_support = min (max (8, 0.002 * m), m);
  ## g = b^e where the base b > 0, else 0
  B = D.x * dirs.';
  on = double (B > 0);
  lb = log (max (B, realmin));
  g = exp (max (lb(:,fam) .* ex, -700)) .* on(:,fam);
  Sgg = s = d = zeros (nch, numel (ex));
  for c = 1:nch
    rr = (c-1)*m+1:c*m;
    r = D.yl(rr) - fcur(rr);
    wl2 = D.wl(rr) .^ 2;
    S1 = sum (wl2);
    Sr = sum (wl2 .* r);
    ## amplitude s >= 0 and a change d of rho_d/pi (rho_d stays >= 0) by
    ## linear least squares
    Sg = wl2.' * g;
    Sgg(c,:) = wl2.' * g .^ 2;
    Sgr = (wl2 .* r).' * g;
    dt = S1 * Sgg(c,:) - Sg .^ 2;
    sc = (S1 * Sgr - Sg * Sr) ./ dt;
    dc = (Sr - sc .* Sg) / S1;
    alone = ! (dt > 0 & sc > 0 & dc >= -p(c) / pi);
    sc(alone) = Sgr(alone) ./ Sgg(c,alone);
    dc(alone) = 0;
    if (nch > 1 && c != D.ref)
      ## no lobe in this channel: rho_d alone
      none = ! (sc > 0 & isfinite (sc));
      sc(none) = 0;
      dc(none) = max (Sr / max (S1, realmin), -p(c) / pi);
    endif
    s(c,:) = sc;
    d(c,:) = dc;
  endfor
  a = s(D.ref,:) .^ (1 ./ ex);
  ## a lobe that lives on a handful of samples is no start
  support = sum (g > 1e-3 * max (g, [], 1), 1);
  ok = Sgg(D.ref,:) > 0 & s(D.ref,:) > 0 & isfinite (a) & a > 0 & support >= min_support;
  C.k = find (ok);
  if (nch == 1)
    C.obj = fit_objective (D, fcur + d(ok) + g(:,ok) .* s(ok));
  else
    F = fcur + kron (d(:,ok), ones (m, 1)) + repmat (g(:,ok), nch, 1) .* kron (s(:,ok), ones (m, 1));
    C.obj = fit_objective (D, F);
  endif
  C.a = a(ok);
  C.d = d(:,ok);
  C.t = s(:,ok) ./ s(D.ref,ok);
  C.dir = dirs(fam(ok),:);
  C.e = ex(ok);
endfunction

## The starts of the candidates I of C (columns) on top of P: the new lobe
## after P's (for shared lobes, its direction and exponent, then the other
## channels' amplitudes)
function P = starts (p, C, i, D)
  lobe = [C.a(i) .* C.dir(i,:).'; C.e(i)];
  if (D.nch > 1)
    lobe = [lobe; C.t([1:D.ref-1, D.ref+1:D.nch],i)];
  endif
  P = [p(:,ones (1, numel (i))); lobe];
  P(1:D.nch,:) = max (p(1:D.nch) + pi * C.d(:,i), 0);
endfunction
