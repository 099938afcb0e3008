## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{P} =} fit_starts (@var{D}, @var{p})
## Candidate starts for one more lobe on top of parameters @var{p}
## (private).  Each candidate lobe (forward/specular, retro-reflective,
## off-specular, near-normal directions; exponents 1 to 1e5) gets its best
## non-negative amplitude by linear least squares against the residual of
## @var{p} on @var{D} (from fit_data); a lobe that is non-negligible on
## fewer than 0.2% of the groups (at least 8) is skipped.  @var{P} holds, as
## columns, the best start of each direction family, best family first.
## @end deftypefn
function P = fit_starts (D, p)
  dirs = [-1 1; 1 1; -1 0.7; -1 1.3; 0 1];
  expo = [1 3 10 30 100 300 1e3 3e3 1e4 3e4 1e5];
  m = rows (D.x);
  min_support = min (max (8, 0.002 * m), m);
  fcur = lafortune_core (p, D.x(:,1), D.x(:,2));
  r = D.yl - fcur;
  wl2 = D.wl .^ 2;
  w2 = D.w .^ 2;
  res0 = w2 .* (D.ty - fit_tf (D, fcur)) .^ 2;
  res_all = sum (res0);
  cand = zeros (0, 5);     # [objective, cxy, cz, e, family]
  for i = 1:rows (dirs)
    b = dirs(i,1) * D.x(:,1) + dirs(i,2) * D.x(:,2);
    on = find (b > 0);
    if (isempty (on))
      continue;
    endif
    ## every exponent at once: g(:,k) = b^expo(k) where b > 0
    g = exp (max (log (b(on)) * expo, -700));
    gg = wl2(on).' * g .^ 2;
    s = (wl2(on) .* r(on)).' * g ./ gg;
    a = s .^ (1 ./ expo);
    ## a lobe that lives on a handful of samples is no start
    support = sum (g > 1e-3 * max (g, [], 1), 1);
    ok = gg > 0 & s > 0 & isfinite (a) & a > 0 & support >= min_support;
    if (! any (ok))
      continue;
    endif
    ## the objective of every candidate at once (fit_objective, by columns)
    s = s(ok); g = g(:,ok);
    res_on = sum (w2(on) .* (D.ty(on) - fit_tf (D, fcur(on) + g .* s)) .^ 2, 1);
    obj = sqrt ((res_all - sum (res0(on)) + res_on + D.wsw) / D.n);
    cand = [cand; obj(:), a(ok)(:) * dirs(i,:), expo(ok)(:), repmat(i, numel (s), 1)];
  endfor
  if (isempty (cand))
    P = zeros (numel (p) + 3, 0);
    return;
  endif
  [~, order] = sort (cand(:,1));
  [~, first] = unique (cand(order,5), "first");
  order = order(sort (first));
  P = [repmat(p, 1, numel (order)); cand(order,2:4).'];
endfunction
