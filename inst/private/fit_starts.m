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
  cand = zeros (0, 5);     # [objective, cxy, cz, e, family]
  for i = 1:rows (dirs)
    b = dirs(i,1) * D.x(:,1) + dirs(i,2) * D.x(:,2);
    on = b > 0;
    if (! any (on))
      continue;
    endif
    lb = log (b(on));
    for e = expo
      g = zeros (m, 1);
      g(on) = exp (max (e * lb, -700));
      gg = sum (wl2 .* g .^ 2);
      if (! (gg > 0))
        continue;
      endif
      s = sum (wl2 .* g .* r) / gg;
      if (! (s > 0))
        continue;
      endif
      a = s ^ (1 / e);
      if (! isfinite (a) || a <= 0)
        continue;
      endif
      ## a lobe that lives on a handful of samples is no start
      if (nnz (g > 1e-3 * max (g)) < min_support)
        continue;
      endif
      cand(end+1,:) = [fit_objective(D, fcur + s * g), a * dirs(i,:), e, i];
    endfor
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
