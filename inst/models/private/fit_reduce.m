## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{j}, @var{xc}] =} fit_reduce (@var{x}, @var{wt}, @var{n})
## Group samples that the isotropic Lafortune model cannot tell apart
## (private).  @var{x} = [a, c] (N x 2: a = ux vx + uy vy, c = uz vz), the
## only way the model sees a pair of directions; @var{wt} (N x 1) the
## samples' weights.  @var{j} (N x 1) is each sample's group, @var{xc} (G x 2)
## the groups' positions.
##
## @var{n} = Inf: groups of equal (a, c), exact (a fit over the groups with
## summed weights and weighted mean values has the same minimiser).
## Otherwise a grid of @var{n} x @var{n} cells in (q, v), q = sqrt (1 - (c -
## a)), v = c + a, placed at the weighted mean (a, c) of its samples.  c - a
## is the base of a forward (specular) lobe, so q is about the angle to the
## mirror direction divided by sqrt (2) and the cells are narrowest there,
## where sharp lobes change fastest; v = wi . wo.
## @end deftypefn
function [j, xc] = fit_reduce (x, wt, n)
  if (isinf (n))
    ## unique (x, "rows"), without its overhead: sorted rows, the first of
    ## each run of equal rows
    [xs, o] = sortrows (x);
    first = [true; any(xs(2:end,:) != xs(1:end-1,:), 2)];
    j = zeros (rows (x), 1);
    j(o) = cumsum (first);
    xc = xs(first,:);
    return;
  endif
  q = sqrt (max (1 - (x(:,2) - x(:,1)), 0)) / sqrt (2);   # [0, 1]
  v = (x(:,2) + x(:,1) + 1) / 2;                          # [0, 1]
  iq = min (max (floor (q * n), 0), n - 1);
  iv = min (max (floor (v * n), 0), n - 1);
  [~, ~, j] = unique (iq * n + iv);
  W = accumarray (j, wt);          # > 0: lafortune_fit leaves zero weights out
  xc = [accumarray(j, wt .* x(:,1)), accumarray(j, wt .* x(:,2))] ./ W;
endfunction
