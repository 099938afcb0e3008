## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{p} =} density_eval (@var{M}, @var{wo}, @var{wi}, @var{j})
## The density in solid angle of component @var{j} of the mixture @var{M}
## (@code{density_mix}) at the directions @var{wi} (N x 3, unit, local
## frame) given @var{wo}, for the rows @var{r} of @var{M} (private, for @code{brdf_sample} and
## @code{brdf_pdf}): cos theta_i / pi above the horizon (0 below), (e + 1)
## / (2 pi) cos^e of the angle to the lobe's axis (0 past 90 degrees from
## it; log space), or the GGX half vectors' D (h) cos theta_h / (4 |wo . h|)
## with h = (wi + wo)/|wi + wo| turned to the upper hemisphere, or a
## tabulated density's: its cell's share over the cell's size in (u, phi)
## and the Jacobians from (u, phi) to h (pi u sin theta_h) and from h to
## wi (4 wo . h); 0 below the horizon.
## @end deftypefn
function p = density_eval (M, wo, wi, j, r)
  switch (M.kind(j))
    case 0
      p = max (wi(:,3), 0) / pi;
    case 1
      c = sum (wi .* M.A{j}(r,:), 2);
      e = M.e(j);
      p = zeros (rows (wi), 1);
      ok = c > 0;
      p(ok) = exp (log ((e + 1) / (2 * pi)) + e * log (min (c(ok), 1)));
    case 2
      h = wi + wo;
      r = sqrt (sum (h .^ 2, 2));
      p = zeros (rows (wi), 1);
      ok = r > 1e-12;
      h = h(ok,:) ./ r(ok);
      ch = min (abs (h(:,3)), 1);
      a2 = M.alpha(j) ^ 2;
      D = a2 ./ (pi * (ch .^ 2 * (a2 - 1) + 1) .^ 2);
      p(ok) = D .* ch ./ (4 * max (abs (sum (h .* wo(ok,:), 2)), realmin));
      p(! isfinite (p)) = 0;
    case 3
      p = table_pdf (M, wo, wi, r);
  endswitch
endfunction

## a tabulated density (density_table) at wi
function p = table_pdf (M, wo, wi, r)
  T = M.T;
  p = zeros (rows (wi), 1);
  h = wi + wo;
  n = sqrt (sum (h .^ 2, 2));
  h ./= max (n, realmin);
  c = sum (h .* wo, 2);
  ok = n > 1e-12 & c > 0 & wi(:,3) > 0;
  if (! any (ok))
    return;
  endif
  az = M.az(r(ok),:);
  hx = h(ok,1) .* az(:,1) + h(ok,2) .* az(:,2);
  hy = h(ok,2) .* az(:,1) - h(ok,1) .* az(:,2);
  th = atan2 (hypot (hx, hy), h(ok,3));
  uu = sqrt (th / (pi / 2));
  iu = min (floor (uu * T.nu) + 1, T.nu);
  ip = min (floor (abs (atan2 (hy, hx)) / pi * T.np) + 1, T.np);
  q = T.P(sub2ind (size (T.P), M.bin(r(ok)), iu, ip)) * (T.nu * T.np / (2 * pi));
  p(ok) = q ./ max (pi * uu .* sin (th) .* 4 .* c(ok), realmin);
  p(! isfinite (p)) = 0;
endfunction
