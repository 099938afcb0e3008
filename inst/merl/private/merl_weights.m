## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{w} =} merl_weights (@var{max_angle}, @var{measure})
## Quadrature weight of every MERL bin (private): the measure, in
## (wi, wo), of the set of direction pairs that the database's lookup puts
## in the bin and that lie in the kept region theta_i, theta_o <=
## @var{max_angle} (degrees).  1458000 x 1, MERL index order.
##
## In half/difference angles, dwi dwo = 4 cos theta_d sin theta_h sin theta_d
## dtheta_h dphi_h dtheta_d dphi_d (checked by Monte Carlo, see
## @code{merl_samples}).  A bin (i, j, k) is theta_h in
## [(i/90)^2, ((i+1)/90)^2] pi/2, theta_d in [j, j+1] pi/180, phi_d in
## [k, k+1] pi/180 and, because the lookup folds them, also phi_d + pi (the
## pair with wi and wo swapped) and every phi_h in [0, 2 pi).  With
## A = cos theta_h cos theta_d and B = sin theta_h sin theta_d,
## cos theta_i = A - B cos phi_d and cos theta_o = A + B cos phi_d (the copy
## at phi_d + pi swaps them), so the kept phi_d are those with
## |cos phi_d| <= (A - cos max_angle) / B: one interval, integrated exactly.
## Summed over both copies and phi_h:
##
## @example
## w = 16 pi  int int cos td sin th sin td  int_@{bin, kept@} P(phi_d) dphi_d dtd dth
## @end example
##
## with P = 1 for @var{measure} @code{"solid_angle"},
## P = A^2 + B^2 cos^2 phi_d (the mean of cos^2 theta_i over the two copies)
## for @code{"cosine"} and P = A^2 - B^2 cos^2 phi_d (cos theta_i
## cos theta_o) for @code{"projected"}.  The theta_h integral is taken in
## u = sqrt (theta_h / (pi/2)) (dtheta_h = pi u du) and the theta_d one with
## 8-point Gauss-Legendre rules per bin.  The last three results are cached.
## @end deftypefn
function w = merl_weights (max_angle, measure)
  persistent keys = {} cache = {}
  k = sprintf ("%.17g/%s", max_angle, measure);
  hit = find (strcmp (keys, k), 1);
  if (! isempty (hit))
    w = cache{hit};
    return;
  endif
  G = 8;
  [x, gw] = gauss_legendre (G);            # on [0, 1]
  c = cosd (max_angle);
  if (max_angle >= 90)
    c = 0;
  endif
  dphi = pi / 180;
  lo = (0:179) * dphi;                     # phi_d bin edges, 1 x 180
  hi = lo + dphi;
  s2lo = sin (2 * lo);
  s2hi = sin (2 * hi);
  c2bin = dphi / 2 + (s2hi - s2lo) / 4;    # int of cos^2 over each whole bin
  sgn = 1;                                 # P = A^2 + sgn B^2 cos^2
  if (strcmp (measure, "projected"))
    sgn = -1;
  endif
  ## theta_d nodes of every theta_d bin: (90 G) x 1, bin j+1 in rows j G + (1:G)
  td = ((0:89) + x(:)) * pi / 180;
  td = td(:);
  wd = repmat (gw(:), 90, 1) * pi / 180;
  bin = repmat (1:90, G * G, 1)(:);        # theta_d bin of each node (G x 90G grid, column major)
  w = zeros (180, 90, 90);                 # phi_d, theta_d, theta_h (index order)
  for i = 0:89
    u = (i + x(:)) / 90;                   # G x 1
    th = u .^ 2 * pi / 2;
    wh = gw(:) / 90 .* (pi * u);           # dtheta_h = pi u du
    [TH, TD] = ndgrid (th, td);            # G x 90G
    A = cos (TH) .* cos (TD);
    B = sin (TH) .* sin (TD);
    g = 16 * pi * cos (TD) .* sin (TH) .* sin (TD) .* (wh .* wd.');
    A = A(:); B = B(:); g = g(:);
    ## kept phi_d in [0, pi]: [a, pi - a], a = acos (q), q = (A - c) / B
    q = (A - c) ./ B;
    q(B == 0) = 2 * (A(B == 0) >= c) - 1;  # all or nothing
    full = q >= 1;
    part = q >= 0 & ! full;
    ## nodes that keep every phi_d: the same integral in every phi_d bin
    if (strcmp (measure, "solid_angle"))
      wk = accumarray (bin(full), g(full), [90 1]) * (dphi * ones (1, 180));
    else
      gA = accumarray (bin(full), g(full) .* A(full) .^ 2, [90 1]);
      gB = accumarray (bin(full), g(full) .* B(full) .^ 2, [90 1]);
      wk = gA * (dphi * ones (1, 180)) + sgn * gB * c2bin;
    endif
    ## nodes that keep part of [0, pi]
    if (any (part))
      qp = q(part);
      a = acos (qp);
      L = max (lo, a);                     # npart x 180
      H = min (hi, pi - a);
      on = H > L;
      len = (H - L) .* on;
      if (strcmp (measure, "solid_angle"))
        v = len;
      else
        ## sin (2 a) = 2 q sqrt (1 - q^2); sin (2 (pi - a)) = -sin (2 a)
        s2a = 2 * qp .* sqrt (1 - qp .^ 2);
        sL = s2lo + (a > lo) .* (s2a - s2lo);
        sH = s2hi - (pi - a < hi) .* (s2a + s2hi);
        c2 = (len / 2 + (sH - sL) / 4) .* on;
        v = A(part) .^ 2 .* len + sgn * B(part) .^ 2 .* c2;
      endif
      wk += accum_rows (bin(part), v .* g(part), 90);
    endif
    w(:,:,i+1) = wk.';
  endfor
  w = w(:);
  keys{end+1} = k;
  cache{end+1} = w;
  if (numel (keys) > 3)                    # keep the last three (12 MB each)
    keys(1) = [];
    cache(1) = [];
  endif
endfunction

function S = accum_rows (j, v, n)
  ## S(r,:) = sum of the rows v(j == r,:)
  S = zeros (n, columns (v));
  if (isempty (j))
    return;
  endif
  [j, ord] = sort (j);
  cs = cumsum (v(ord,:), 1);
  m = numel (j);
  last = [find(diff (j)); m];
  tot = cs(last,:);
  tot(2:end,:) -= cs(last(1:end-1),:);
  S(j(last),:) = tot;
endfunction

function [x, w] = gauss_legendre (n)
  ## Golub-Welsch on [0, 1]
  k = 1:n-1;
  b = k ./ sqrt (4 * k .^ 2 - 1);
  [V, D] = eig (diag (b, 1) + diag (b, -1));
  [x, o] = sort (diag (D));
  w = 2 * V(1,o)' .^ 2;
  x = (x + 1) / 2;
  w = w / 2;
endfunction
