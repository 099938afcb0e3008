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
## (1 - u), reflected: wi = 2 (wo . h) h - wo.
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
