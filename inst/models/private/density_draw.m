## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{wi} =} density_draw (@var{M}, @var{wo}, @var{j}, @var{u}, @var{v})
## Directions drawn from component @var{j} of the mixture @var{M}
## (@code{density_mix}) for the rows @var{r} of @var{M}, views @var{wo}, by the uniforms @var{u},
## @var{v} (columns in [0, 1); private, for @code{brdf_sample}): the
## cosine-weighted hemisphere; a cosine power about the lobe's axis,
## cos alpha = (1 - u)^(1/(e+1)) (log space, so that exponents of 1e7
## keep their angle); or a GGX half vector, tan^2 theta_h = alpha^2 u /
## (1 - u), reflected: wi = 2 (wo . h) h - wo; or a tabulated density's
## half vector: a cell of the view's table by @var{u} (its u marginal) and
## @var{v} (phi within the row, the first half of [0, 1) for phi >= 0, the
## second for phi < 0), then uniform within the cell, reflected.
## @end deftypefn
function wi = density_draw (M, wo, j, u, v, r)
  ph = 2 * pi * v;
  switch (M.kind(j))
    case 0
      r = sqrt (u);
      wi = [r .* cos(ph), r .* sin(ph), sqrt(max (1 - u, 0))];
    case 1
      l = log1p (-u) / (M.e(j) + 1);
      ca = exp (l);
      sa = sqrt (max (-expm1 (2 * l), 0));
      N = M.A{j}(r,:);
      [T, B] = frame_of (N);
      wi = (sa .* cos (ph)) .* T + (sa .* sin (ph)) .* B + ca .* N;
    case 2
      a2 = M.alpha(j) ^ 2;
      t2 = a2 * u ./ max (1 - u, realmin);
      ch = 1 ./ sqrt (1 + t2);
      sh = sqrt (t2 ./ (1 + t2));
      h = [sh .* cos(ph), sh .* sin(ph), ch];
      wi = 2 * sum (wo .* h, 2) .* h - wo;
    case 3
      wi = table_draw (M, wo, u, v, r);
  endswitch
  wi ./= sqrt (sum (wi .^ 2, 2));
endfunction

## an orthonormal completion T, B of unit vectors N (rows; Duff et al. 2017)
function [T, B] = frame_of (N)
  s = 2 * (N(:,3) >= 0) - 1;
  a = -1 ./ (s + N(:,3));
  b = N(:,1) .* N(:,2) .* a;
  T = [1 + s .* N(:,1) .^ 2 .* a, s .* b, -s .* N(:,1)];
  B = [b, s + N(:,2) .^ 2 .* a, -N(:,2)];
endfunction

## a tabulated density's draws (density_table): cell, place in the cell, h, wi
function wi = table_draw (M, wo, u, v, r)
  T = M.T;
  b = M.bin(r);
  [iu, fu] = cdf_find (T.cu, b, u);
  neg = v >= 0.5;
  v = 2 * v - neg;
  [ip, fp] = cdf_find (T.cp, (b - 1) * T.nu + iu, v);
  th = pi / 2 * ((iu - 1 + fu) / T.nu) .^ 2;
  ph = (ip - 1 + fp) / T.np * pi .* (1 - 2 * neg);
  hx = sin (th) .* cos (ph);
  hy = sin (th) .* sin (ph);
  az = M.az(r,:);
  h = [hx .* az(:,1) - hy .* az(:,2), hx .* az(:,2) + hy .* az(:,1), cos(th)];
  wi = 2 * sum (wo .* h, 2) .* h - wo;
endfunction

## per row k of the cumulative rows C(R,:) (each ending at its total), the
## cell of x C(R,end) (bisection) and x's place within it, in [0, 1)
function [k, f] = cdf_find (C, R, x)
  n = columns (C);
  tot = C(sub2ind (size (C), R, repmat (n, size (R))));
  x = x .* tot;
  lo = zeros (size (R));
  hi = repmat (n, size (R));
  while (any (hi - lo > 1))
    mid = floor ((lo + hi) / 2);
    go = C(sub2ind (size (C), R, max (mid, 1))) < x;
    lo(go) = mid(go);
    hi(! go) = mid(! go);
  endwhile
  k = hi;
  a = zeros (size (R));
  a(k > 1) = C(sub2ind (size (C), R(k > 1), k(k > 1) - 1));
  c = C(sub2ind (size (C), R, k));
  f = min (max ((x - a) ./ max (c - a, realmin), 0), 1 - eps);
endfunction
