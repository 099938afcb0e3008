## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {[@var{model}, @var{models}, @var{info}] =} fit_lafortune (@var{S}, @var{wt}, @var{n0}, @var{nlobes}, @var{opt})
## lafortune_fit's engine (private), as fit_model is brdf_fit's: @var{S}
## is the checked table (with a scene table's prior appended after row
## @var{n0}), @var{wt} its weights, @var{opt} lafortune_fit's checked
## options.  Returns the fit of @var{nlobes} lobes, the fits of 1 ..
## @var{nlobes} lobes of a growing fit (the one fit otherwise) and
## lafortune_fit's @var{info}.  The Lafortune lobe sees a pair only
## through (a, c) = (ux vx + uy vy, uz vz): samples equal in those are
## merged (fit_reduce; a large table on the cells of a grid), each channel
## (or the channels sharing lobes, fit_stack) is fitted by fit_channel in
## scaled units, and a growing fit is guarded (fit_guard) and screens its
## starts on a coarse grid (groups below).
## @end deftypefn

function [model, models, info] = fit_lafortune (S, wt, n0, nlobes, opt)
  N = rows (S.wi);
  def = __lafortune_model_def__ ("lafortune");
  xall = def.coords ("x", [], S);
  ## a sample of weight 0 is left out of the fit; the metrics, the scale
  ## and the scaled data (fit_setup)
  keep = wt > 0;
  F = fit_setup (S, n0, keep, opt, "lafortune_fit");
  [Srep, rep, names, Sf, Ss, sc, fspec, pspec] = deal (F.Srep, F.rep, F.names, F.Sf, F.Ss, F.sc,
                                                     F.fspec, F.pspec);
  iref = F.iref;
  shared = strcmp (opt.color, "shared");
  x = xall(keep,:);
  ## the coarse grid for starts and the guard are for the growing fit only
  ## (from a given start, one run: fit_channel)
  grow = strcmp (opt.init, "grow") && isempty (opt.start);
  [j, xc, xr, info_reduce, jg, jrep] = groups (x, wt(keep), opt, grow);
  G = [];
  if (grow && isfield (S, "kind") && strcmp (S.kind, "scene"))
    ## a scene table: every pair a normal can make at its angles between
    ## light and viewer (the table itself has gaps between its pixels)
    G = fit_guard ("scene", x, sum (Sf.wi .* Sf.wo, 2));
  elseif (grow)
    G = fit_guard (min ([Sf.wi(:,3); Sf.wo(:,3)]));
  endif
  z = zeros (nlobes, 3);
  model = struct ("rho_d", [0 0 0], "Cxy", z, "Cz", z, "e", z + 1);
  models = cell (1, nlobes);
  for k = 1:nlobes
    models{k} = struct ("rho_d", [0 0 0], "Cxy", zeros (k, 3), "Cz", zeros (k, 3), "e", ones (k, 3));
  endfor
  nan3 = nan (1, 3);
  info = struct ("nlobes", nlobes, "weight", opt.weight, "color", opt.color, "n", rows (x),
                 "groups", rows (xc), "reduce", info_reduce,
                 "rmse", nan3, "rel_rmse", nan3, "log_rmse", nan3, "cos_rmse", nan3,
                 "error", nan3,
                 "iterations", zeros (1, 3), "full_iterations", zeros (1, 3),
                 "rejected", zeros (1, 3), "converged", true (1, 3), "time", zeros (1, 3),
                 "trace", {cell(1, 3)}, "history", nan (nlobes, 3),
                 "lobe_time", nan (nlobes, 3));
  traces = cell (1, 3);
  if (shared)
    [models, info, traces] = fit_shared (Ss, Sf, fspec, pspec, sc, iref, j, xc, xr, jg, jrep, G,
                                         nlobes, opt, models, info);
    model = models{nlobes};
  endif
  separate = opt.channels(:)';         # each channel alone (none when shared)
  if (shared)
    separate = [];
  endif
  for c = separate
    t0 = tic ();
    [D, R] = channel_data (Ss, Sf, fspec, pspec, sc, c, j, xc, xr, jg, jrep, opt);
    ## a given start (in the data's units), or none: grow lobe by lobe
    p0 = [];
    if (! isempty (opt.start))
      p0 = model_params (opt.start, c);
    elseif (strcmp (opt.init, "plain"))
      p0 = plain_start (nlobes, 1);
    endif
    if (! isempty (p0))
      p0 = def.coords ("unscale", [], p0, 1 / sc(c));
    endif
    ch = fit_channel (D, R, nlobes, opt, G, p0);
    for k = 1:numel (ch.ps)
      if (! isempty (ch.ps{k}))
        models{k} = set_params (models{k}, c, def.coords ("unscale", [], ch.ps{k}, sc(c)));
      endif
    endfor
    model = models{nlobes};
    info = channel_info (info, c, toc (t0), ch, nlobes, opt);
    traces{c} = ch.trace;
  endfor
  ## the reported errors: brdf_error's values (metric_spec's finish) of
  ## the models evaluated as it evaluates them (lafortune_eval: 0 on or below
  ## the horizon); a channel not fitted has the zero model
  Fk = {};
  if (grow)
    Fk = cellfun (@(m) lafortune_eval (m, Srep.wi, Srep.wo), models(1:nlobes-1), "uniformoutput", false);
  endif
  fitted = false (1, 3);
  fitted(opt.channels) = true;
  info = fit_errors (info, rep, names, lafortune_eval (model, Srep.wi, Srep.wo), Fk, fitted,
                     opt.weight);
  ## (with a prior the trace's rows are on every fitted row: the last row is
  ## then the table's rmse)
  for c = opt.channels(:)'
    info.trace{c} = fit_trace (traces{c}, info.time(c), info.rmse(c),
                                strcmp (info_reduce, "exact") && n0 >= N);
  endfor
  if (! grow)
    models = {model};
  endif
endfunction

## One channel's data D (fit_data, scaled units) and its coarse grid R
function [D, R] = channel_data (Ss, Sf, fspec, pspec, sc, c, j, xc, xr, jg, jrep, opt)
  D = fit_data (fspec, c, j, xc, Ss.rgb(:,c), sc(c), pspec, Sf.rgb(:,c), "lafortune_fit");
  D.def = __lafortune_model_def__ ("lafortune");       # the fit's coordinates
  R = D;
  if (rows (xr) != rows (xc))
    R = fit_data ("coarse", D, jg, jrep);
  endif
endfunction

## The fit with lobes shared across the channels (opt.channels): their
## data stacked (fit_stack) and fitted as one problem (fit_channel), with
## the reference channel IREF (its position among opt.channels) and one
## scale SC for all; the models get each channel's folded lobes
function [models, info, traces] = fit_shared (Ss, Sf, fspec, pspec, sc, iref, j, xc, xr, jg, jrep, G,
                                              nlobes, opt, models, info)
  t0 = tic ();
  chs = opt.channels(:)';
  nch = numel (chs);
  Ds = Rs = cell (1, nch);
  for i = 1:nch
    [Ds{i}, Rs{i}] = channel_data (Ss, Sf, fspec, pspec, sc, chs(i), j, xc, xr, jg, jrep, opt);
  endfor
  D = fit_stack (Ds, iref);
  R = fit_stack (Rs, iref);
  s = sc(chs(1));
  p0 = [];
  if (! isempty (opt.start))
    p0 = shared_lobes ("join", arrayfun (@(c) model_params (opt.start, c), chs, "uniformoutput", false),
                       iref);
  elseif (strcmp (opt.init, "plain"))
    p0 = plain_start (nlobes, nch);
  endif
  if (! isempty (p0))
    p0 = D.def.coords ("unscale", D, p0, 1 / s);
  endif
  ch = fit_channel (D, R, nlobes, opt, G, p0);
  for k = 1:numel (ch.ps)
    if (! isempty (ch.ps{k}))
      P = shared_lobes ("split", D.def.coords ("unscale", D, ch.ps{k}, s), iref, nch);
      for i = 1:nch
        models{k} = set_params (models{k}, chs(i), P{i});
      endfor
    endif
  endfor
  traces = cell (1, 3);
  t = toc (t0);
  for i = 1:nch
    info = channel_info (info, chs(i), t, ch, nlobes, opt, i == 1);
    traces{chs(i)} = ch.trace(:,[1 2 2+i]);
  endfor
endfunction

## The paper's naive start for NCH channels: rho_d = 0.1, lobe k: Cxy = -1,
## Cz = 1, e = 10 k (for shared lobes, every channel's amplitude 1)
function p0 = plain_start (nlobes, nch)
  lobe = [-1; 1; 0; ones(nch - 1, 1)];
  p0 = [0.1 * ones(nch, 1); repmat(lobe, nlobes, 1)];
  p0(nch+3:2+nch:end) = 10 * (1:nlobes);
endfunction

## INFO's per-channel counts of channel C from the fit CH (T seconds)
function info = channel_info (info, c, t, ch, nlobes, opt, warn = true)
  info.time(c) = t;
  info.iterations(c) = ch.iter;
  info.full_iterations(c) = ch.full_iter;
  info.rejected(c) = ch.rejected;
  info.converged(c) = ch.cvg;
  info.lobe_time(:,c) = ch.ktime(:);
  if (! ch.cvg && warn)
    warning ("lafortune:notConverged",
             "lafortune_fit: channel %d (%d lobes) did not converge in %d iterations; the parameters are finite but may not be optimal",
             c, nlobes, opt.max_iter);
  endif
endfunction

## The groups the fit runs on (J, XC: exact equal (a, c) pairs, or grid
## cells when there are more than AUTO_GROUPS samples, or as "reduce" says)
## and the coarse grid that screens starts (JG: each group's cell, XR: the
## cells' positions; about "screen_samples" cells, or the groups themselves
## when there are no more than that, or when COARSE is false), and for each
## cell the group nearest its position (REP), which stands for it in
## fit_data's coarse data.
function [j, xc, xr, how, jg, rep] = groups (x, wt, opt, coarse)
  AUTO_GROUPS = 20000;
  AUTO_GRID = 512;
  if (isnumeric (opt.reduce))
    n = opt.reduce;
  elseif (strcmp (opt.reduce, "auto") && rows (x) > AUTO_GROUPS)
    n = AUTO_GRID;
  else
    n = Inf;
  endif
  [j, xc] = fit_reduce (x, wt, n);
  if (isinf (n))
    how = "exact";
  else
    how = sprintf ("grid %d", n);
  endif
  xr = xc; jg = (1:rows (xc))'; rep = jg;
  if (coarse && rows (xc) > opt.screen_samples)
    ## coarsen the groups (cells of about the wanted count)
    gw = accumarray (j, wt);
    n = 2 ^ ceil (log2 (sqrt (opt.screen_samples)));
    while (true)
      [jg, xr] = fit_reduce (xc, gw, n);
      if (rows (xr) >= opt.screen_samples / 2 || n >= 4096)
        break;
      endif
      n *= 2;
    endwhile
    d = sum ((xc - xr(jg,:)) .^ 2, 2);
    [~, o] = sortrows ([jg d]);
    first = true (numel (o), 1);
    first(2:end) = jg(o(2:end)) != jg(o(1:end-1));
    rep = zeros (rows (xr), 1);
    rep(jg(o(first))) = o(first);
  endif
endfunction

function p = model_params (m, c)
  p = [m.rho_d(c); reshape([m.Cxy(:,c) m.Cz(:,c) m.e(:,c)].', [], 1)];
endfunction

function m = set_params (m, c, p)
  m.rho_d(c) = p(1);
  L = reshape (p(2:end), 3, []).';
  m.Cxy(:,c) = L(:,1); m.Cz(:,c) = L(:,2); m.e(:,c) = L(:,3);
endfunction
