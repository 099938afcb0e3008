## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {[@var{model}, @var{info}, @var{models}] =} fit_select (@var{V}, @var{nlobes}, @var{front})
## The general fit's choice (private, both fronts), in two stages as Bieron
## and Peers 2020 choose: fit the table with each candidate weighting
## @var{W} (@code{front (w)} is the front called with @qcode{"weight"},
## @var{w}: @code{[model, info, models]}), render every fit of 1 to
## @var{nlobes} lobes in the training views @var{V} (fit_views: rt_render
## from their caches) and keep, for each lobe count k, the fit of at most k
## lobes whose mean FLIP over the views is lowest (a fit of fewer lobes is
## padded with lobes of zero amplitude, so a k-lobe result has k lobes).
## The views' FLIP so never rises with a lobe.  A fit whose render is not
## finite in a view (a lobe that lives beyond the table's grazing cut,
## which the sphere's rim sees) scores Inf and is kept only when nothing
## else is left.
##
## @var{info} is the chosen k-lobe fit's, with @code{weight} its weighting,
## @code{time} the sum over the candidates and @code{selection}:
## @code{weights} (the candidates), @code{flip} (candidates x lobes: each
## fit's mean FLIP in the views), @code{chosen} (1 x nlobes: the index of
## the weighting kept for each lobe count), @code{lobes} (1 x nlobes: its
## lobe count before padding), @code{views} (the number of views) and
## @code{time} (the renders and comparisons, seconds).
## @end deftypefn

function [model, info, models] = fit_select (V, nlobes, front)
  ## the candidates: the hemisphere table's weightings that the held-out
  ## measurement over 26 materials left in (README, "One fit for every scene")
  W = {"log", "cuberoot"};
  nw = numel (W);
  F = NaN (nw, nlobes);
  all_models = cell (nw, nlobes);
  infos = cell (1, nw);
  ts = 0;
  for i = 1:nw
    [~, infos{i}, all_models(i,:)] = front (W{i});
    t0 = tic ();
    for k = 1:nlobes
      F(i,k) = view_flip (V, all_models{i,k});
    endfor
    ts += toc (t0);
  endfor
  ## for each k the best of every fit with at most k lobes; ties keep the
  ## fewer lobes, then the earlier candidate
  chosen = zeros (1, nlobes);
  lobes = zeros (1, nlobes);
  models = cell (1, nlobes);
  best = Inf;
  for k = 1:nlobes
    [f, i] = min (F(:,k));
    if (k == 1 || f < best)
      best = f;
      chosen(k) = i;
      lobes(k) = k;
    else
      chosen(k) = chosen(k-1);
      lobes(k) = lobes(k-1);
    endif
    models{k} = pad_lobes (all_models{chosen(k), lobes(k)}, k);
  endfor
  model = models{nlobes};
  info = infos{chosen(nlobes)};
  info.weight = W{chosen(nlobes)};
  time = 0;
  for i = 1:nw
    time += infos{i}.time;
  endfor
  info.time = time;
  info.selection = struct ("weights", {W}, "flip", F, "chosen", chosen, "lobes", lobes,
                           "views", numel (V), "time", ts);
endfunction

## the mean FLIP of model M over the views V
function f = view_flip (V, m)
  f = 0;
  for v = V(:)'
    img = rt_render (v.scene, m, "progress", false, "cache", v.cache);
    if (! all (isfinite (img(:))))
      f = Inf;                           # a lobe beyond the table's angles
      return;
    endif
    f += img_flip (v.ref, img);
  endfor
  f /= numel (V);
endfunction

## model M with lobes of zero amplitude added up to K lobes (the shapes of
## its last lobe, so every field stays in its bounds)
function m = pad_lobes (m, k)
  if (isfield (m, "ks"))
    amp = {"ks"};
  else
    amp = {"Cxy", "Cz"};                 # Lafortune: a lobe of base 0 is 0
  endif
  n = rows (m.(amp{1}));
  if (n >= k)
    return;
  endif
  for f = fieldnames (m)'
    v = m.(f{1});
    if (isnumeric (v) && rows (v) == n && columns (v) == 3 && ! strcmp (f{1}, "rho_d"))
      m.(f{1}) = [v; repmat(merge (any (strcmp (f{1}, amp)), 0, 1) .* v(end,:), k - n, 1)];
    endif
  endfor
endfunction
