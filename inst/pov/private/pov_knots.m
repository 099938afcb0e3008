## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{K} =} pov_knots (@var{x}, @var{G}, @var{W}, @var{M}, @var{tol}, @var{nmax}, @var{mode})
## Choose the entries of piecewise-linear tables (private, for
## @code{pov_write_scene}).
##
## @var{G} is @var{n} x @var{m} x @var{B}: @var{B} independent tables, each
## sampled densely at the @var{n} ascending points @var{x} along the table
## axis (dimension 1; not necessarily evenly spaced); the
## @var{m} columns are functions that share the entries (the error is the
## maximum over them).  @var{W} (weights) and @var{M} (logical mask: where the
## error counts) broadcast to the size of @var{G}.  For each table the first
## and last rows with any @var{M} are always entries; rows outside them are
## not interpolated.
##
## @var{mode} @qcode{"uniform"}: @var{nmax} entries, the dense points nearest
## to even spacing between those two.  @qcode{"adaptive"}: greedy refinement,
## starting from the two end entries: the interval with the largest weighted
## error |@var{W} (@var{G} - linear interpolation)| is split at the dense point
## of that error, until no interval exceeds @var{tol} or the table has
## @var{nmax} entries.  A single table is refined one interval at a time;
## many tables together in vectorised passes that split, in each table, every
## interval within a factor 2 of its worst (same result once all are under
## @var{tol}, nearly the same order otherwise).  With sharp features (narrow
## lobes) this puts the entries where the function bends.  A table that runs
## out of entries before its error is under @var{tol} is made again from
## @var{nmax}/4 evenly spaced entries and refined greedily from there: its
## sharp part would otherwise take every entry and leave the rest to one
## long interval (a measured material's specular peak can be orders of
## magnitude above its diffuse level).
##
## @var{K} is @var{n} x @var{B} logical: the entries of each table.
## @end deftypefn
function K = pov_knots (x, G, W, M, tol, nmax, mode)
  x = x(:);
  [n, m, B] = size (G);
  W = W .* ones (size (G));
  M = logical (M) & true (size (G));
  act = reshape (any (M, 2), n, B);
  K = false (n, B);
  first = ones (1, B);
  last = n * ones (1, B);
  for b = 1:B
    r = find (act(:,b));
    if (! isempty (r))
      first(b) = r(1);
      last(b) = r(end);
    endif
  endfor
  if (strcmp (mode, "uniform"))
    K = uniform (x, first, last, nmax);
    return;
  endif
  K(sub2ind ([n B], first, 1:B)) = true;
  K(sub2ind ([n B], last, 1:B)) = true;
  K0 = K;
  K = refine (x, G, W, M, tol, nmax, first, last, K);
  ## tables out of entries: again, from an even base
  full = find (sum (K, 1) >= nmax & nmax >= 8);
  if (! isempty (full))
    Kb = K0(:,full) | uniform (x, first(full), last(full), floor (nmax / 4));
    K(:,full) = refine (x, G(:,:,full), W(:,:,full), M(:,:,full), tol, nmax,
                        first(full), last(full), Kb);
  endif
endfunction

function K = refine (x, G, W, M, tol, nmax, first, last, K)
  if (size (G, 3) == 1)
    K = greedy_one (x, G, W, M, tol, nmax, first, last, K);
  else
    K = refine_batch (x, G, W, M, tol, nmax, first, last, K);
  endif
endfunction

## the dense points nearest to NE evenly spaced points from x(FIRST) to
## x(LAST), per table (n x numel (FIRST) logical)
function K = uniform (x, first, last, ne)
  n = numel (x);
  K = false (n, numel (first));
  for b = 1:numel (first)
    v = linspace (x(first(b)), x(last(b)), ne)';
    i = max (lookup (x, v), 1);
    j = min (i + 1, n);
    up = abs (x(j) - v) < abs (x(i) - v);
    i(up) = j(up);
    K(i, b) = true;
  endfor
endfunction

## One table with many columns: one interval at a time, recomputing only the
## two halves of the interval just split.  The oct-file __pov_knots__ does
## the same operations, compiled (this code is the reference; the tests
## compare the two bit for bit); it is used when built.
function K = greedy_one (x, G, W, M, tol, nmax, first, last, K)
  kn = find (K(:,1));
  kn = kn(kn >= first & kn <= last);
  if (numel (kn) >= 2)
    [done, k] = __lafortune_oct_call__ ("__pov_knots__", "pov_knots", x, G, W, M, tol, nmax, kn);
    if (done)
      K(k) = true;
      return;
    endif
  endif
  e = a = zeros (numel (kn) - 1, 1);
  for j = 1:numel (kn) - 1
    [e(j), a(j)] = interval_err (x, G, W, M, kn(j), kn(j+1));
  endfor
  while (numel (kn) < nmax)
    [emax, j] = max (e);
    if (! (emax > tol))
      break;
    endif
    p = a(j);
    [e1, a1] = interval_err (x, G, W, M, kn(j), p);
    [e2, a2] = interval_err (x, G, W, M, p, kn(j+1));
    kn = [kn(1:j); p; kn(j+1:end)];
    e = [e(1:j-1); e1; e2; e(j+1:end)];
    a = [a(1:j-1); a1; a2; a(j+1:end)];
  endwhile
  K(kn) = true;
endfunction

function [emax, amax] = interval_err (x, G, W, M, lo, hi)
  emax = 0;
  amax = lo;
  if (hi - lo < 2)
    return;
  endif
  r = (lo+1:hi-1)';
  t = (x(r) - x(lo)) / (x(hi) - x(lo));
  E = W(r,:) .* abs (G(r,:) - ((1 - t) .* G(lo,:) + t .* G(hi,:)));
  E(! M(r,:)) = 0;
  [emax, i] = max (E(:));
  amax = r(mod (i - 1, numel (r)) + 1);
endfunction

## Many tables with few columns: passes vectorised over all tables.  The
## oct-file __pov_knots_batch__, when it is built, makes the same passes.
function K = refine_batch (x, G, W, M, tol, nmax, first, last, K)
  [done, Kc] = __lafortune_oct_call__ ("__pov_knots_batch__", "pov_knots", x, G, W, M, tol, nmax,
                                       first, last, K);
  if (done)
    K = Kc;
    return;
  endif
  [n, m, B] = size (G);
  idx = (1:n)';
  M &= reshape (idx >= first & idx <= last, n, 1, B);
  off = n * (0:m-1) + n * m * reshape (0:B-1, 1, 1, B);   # 1 x m x B
  while (true)
    ## linear interpolation between the current entries, all tables at once
    prev = max (cummax (K .* idx, 1), 1);
    nxt = min (flipud (cummin (flipud (K .* idx + (! K) * (n + 1)), 1)), n);
    t = reshape ((x(idx) - x(prev)) ./ max (x(nxt) - x(prev), realmin), n, 1, B);
    lin = (1 - t) .* G(reshape (prev, n, 1, B) + off) ...
          + t .* G(reshape (nxt, n, 1, B) + off);
    E = W .* abs (G - lin);
    E(! M) = 0;
    E = reshape (max (E, [], 2), n, B);
    E(K) = 0;
    ## split the intervals whose error exceeds TOL and is within a factor 2
    ## of the table's worst, at their worst point: the worst go first, as
    ## one at a time, and the result once under TOL is the same
    key = prev + n * (0:B-1);                  # interval = its left entry
    emax = accumarray (key(:), E(:), [n*B 1], @max);
    bar = max (tol, 0.5 * max (E, [], 1));
    cand = find (E > tol & E >= bar & E >= reshape (emax(key), n, B));
    if (isempty (cand))
      break;
    endif
    [~, ia] = unique (key(cand), "first");
    sel = cand(ia);
    b = ceil (sel / n);
    room = nmax - sum (K, 1);
    cnt = accumarray (b, 1, [B 1])';
    over = find (cnt > room);
    drop = false (size (sel));
    for j = over                               # keep the worst intervals
      in = find (b == j);
      [~, o] = sort (E(sel(in)), "descend");
      drop(in(o(room(j)+1:end))) = true;
    endfor
    sel(drop) = [];
    if (isempty (sel))
      break;
    endif
    K(sel) = true;
  endwhile
endfunction
