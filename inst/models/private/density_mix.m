## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{M} =} density_mix (@var{P}, @var{wo})
## The mixture a sampling density is at the viewing directions @var{wo}
## (N x 3, local frame, unit; private, for @code{brdf_sample} and
## @code{brdf_pdf}), from @var{P} of @code{density_prep}.  Component 1 is
## the cosine-weighted hemisphere; then one per lobe and channel: for a
## Lafortune lobe the cosine power cos^e around its axis a = (Cxy vx, Cxy
## vy, Cz vz)/|(...)| with weight |a|^e 2 pi/(e+1) max (a_z, 0.05) (the
## lobe's integral, log space), for the other types a GGX half-vector
## distribution.  Fields: @code{W} (N x nc, rows summing to 1),
## @code{kind} (1 x nc: 0 cosine, 1 cosine power, 2 GGX), @code{e},
## @code{alpha} (1 x nc), @code{A} (1 x nc cell: the power lobes' axes, N x 3).
## A row with no weight (a black model) samples the cosine alone.  A
## tabulated density (@code{density_table}) is the cosine (weight
## @code{P.wd}) and the table of the view's theta_o bin (kind 3; fields
## @code{T}, the table, @code{bin}, each view's bin, and @code{az}, the
## cosine and sine of each view's azimuth); a view whose bin is empty
## samples the cosine alone.
## @end deftypefn
function M = density_mix (P, wo)
  n = rows (wo);
  if (P.table)
    M = table_mix (P, wo);
    return;
  endif
  if (P.lafortune)
    nc = numel (P.e);
    A = cell (1, nc);
    lw = -Inf (n, nc);
    for j = 1:nc
      a = [P.cxy(j) * wo(:,1:2), P.cz(j) * wo(:,3)];
      r = sqrt (sum (a .^ 2, 2));
      A{j} = a ./ max (r, realmin);
      ok = r > 0;
      e = P.e(j);
      lw(ok,j) = e * log (r(ok)) + log (2 * pi / (e + 1)) + log (max (A{j}(ok,3), 0.05)) - log (3);
    endfor
    kind = [0, ones(1, nc)];
    e = [0, P.e];
    alpha = zeros (1, nc + 1);
  else
    nc = numel (P.wk);
    A = cell (1, nc);
    lw = repmat (log (P.wk), n, 1);
    kind = [0, 2 * ones(1, nc)];
    e = zeros (1, nc + 1);
    alpha = [0, P.alpha];
  endif
  lw = [repmat(log (P.wd), n, 1), lw];
  mx = max (lw, [], 2);
  dead = ! isfinite (mx);
  lw(dead,:) = -Inf;
  lw(dead,1) = 0;
  mx(dead) = 0;
  W = exp (lw - mx);
  W ./= sum (W, 2);
  M = struct ("W", W, "kind", kind, "e", e, "alpha", alpha, "A", {[{[]}, A]});
endfunction

function M = table_mix (P, wo)
  T = P.model;
  to = acos (min (max (wo(:,3), -1), 1));
  bin = min (max (floor (to / (pi / 2) * T.nt) + 1, 1), T.nt);
  r = hypot (wo(:,1), wo(:,2));
  az = [wo(:,1), wo(:,2)] ./ r;
  az(! (r > 0), :) = repmat ([1 0], sum (! (r > 0)), 1);
  full = T.cu(bin,end) > 0;
  W = [repmat(P.wd, rows (wo), 1), repmat(1 - P.wd, rows (wo), 1)];
  W(! full,:) = repmat ([1 0], sum (! full), 1);
  M = struct ("W", W, "kind", [0 3], "e", [0 0], "alpha", [0 0], "A", {{[], []}}, "T", T,
              "bin", bin, "az", az);
endfunction
