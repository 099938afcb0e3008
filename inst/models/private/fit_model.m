## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {[@var{models}, @var{info}] =} fit_model (@var{S}, @var{wt}, @var{n0}, @var{def}, @var{nlobes}, @var{opt})
## brdf_fit's engine for a physically based model (private).  @var{S} is
## the checked table (with a scene table's prior appended after row
## @var{n0}), @var{wt} its weights, @var{def} the type (model_def).
## Returns the models of 1 .. @var{nlobes} lobes (data units) and
## brdf_fit's @var{info}.
##
## The model sees a pair only through (cos theta_i, cos theta_o, wi.wo),
## so samples equal in those are merged (fit_reduce, exact; a large table,
## such as a scene table's prior of the whole hemisphere, on cells of a grid,
## see groups below); samples on or
## below the horizon, where every model is 0, and of weight 0 are left out.
## The data are divided by their largest magnitude per channel (one for all
## with "shared"): rho_d and ks scale with the data, the shape does not,
## so the fit is scale invariant.  Lobes are added one at a time
## (grow_lobe): every candidate shape of the type's grid gets its best
## amplitude and change of rho_d by linear least squares, the best
## @code{opt.tries} start a leasqr run each (fit_lm, in fit_phys's
## coordinates), and the best accepted result that lowers the objective is
## kept, so that the error never rises with more lobes.  A result that is
## not finite or larger than 10 times the data's maximum on the data's
## groups is rejected.  (Lafortune's guard also checks an in-plane grid
## between the samples, where a Lafortune lobe, whose amplitude enters
## through its base, can explode; these models' lobes are normalised
## shapes with bounded parameters, and a true microfacet lobe legitimately
## exceeds the data's maximum at grazing mirror angles the data do not
## sample: that check rejected exact fits.)  With
## @code{opt.energy}, a result whose albedo exceeds 1 is refitted by
## @code{sqp} under the constraint (fit_energy).
## @end deftypefn

function [models, info] = fit_model (S, wt, n0, def, nlobes, opt)
  fname = "brdf_fit";
  N = rows (S.wi);
  keep = wt > 0 & S.wi(:,3) > 0 & S.wo(:,3) > 0;
  F = fit_setup (S, n0, keep, opt, fname);
  [Srep, rep, names, Sf, Ss, sc, fspec, pspec] = deal (F.Srep, F.rep, F.names, F.Sf, F.Ss, F.sc,
                                                     F.fspec, F.pspec);
  shared = strcmp (opt.color, "shared");
  X = def.coords ("x", [], Sf);
  [j, xc, how] = groups (X, wt(keep), opt.reduce);
  nan3 = nan (1, 3);
  info = struct ("type", def.type, "nlobes", nlobes, "weight", opt.weight, "color", opt.color,
                 "n", rows (X), "groups", rows (xc), "reduce", how,
                 "rmse", nan3, "rel_rmse", nan3, "log_rmse", nan3, "cos_rmse", nan3,
                 "error", nan3, "iterations", zeros (1, 3), "full_iterations", zeros (1, 3),
                 "rejected", zeros (1, 3), "converged", true (1, 3), "time", zeros (1, 3),
                 "trace", {cell(1, 3)}, "history", nan (nlobes, 3),
                 "lobe_time", nan (nlobes, 3), "albedo", zeros (1, 3), "albedo_lobes", zeros (nlobes, 3), "energy", true (1, 3),
                 "enforced", false (1, 3));
  P0 = zeros (1 + nlobes * (1 + numel (def.shape)), 3);
  Ps = repmat ({P0}, 1, nlobes);
  for k = 1:nlobes
    Ps{k} = P0(1:1 + k * (1 + numel (def.shape)),:);
    Ps{k}(3 + (0:k-1) * (1 + numel (def.shape)),:) = def.lo(2);   # shape at its bound
    if (numel (def.shape) > 1)
      Ps{k}(4 + (0:k-1) * (1 + numel (def.shape)),:) = def.lo(3);
    endif
  endfor
  Ds = cell (1, 3);
  for c = opt.channels(:)'
    Ds{c} = fit_data (fspec, c, j, xc, Ss.rgb(:,c), sc(c), pspec, Sf.rgb(:,c), fname);
  endfor
  if (shared)
    blocks = {opt.channels(:)'};
  else
    blocks = num2cell (opt.channels(:)');
  endif
  traces = cell (1, 3);
  for b = 1:numel (blocks)
    B = blocks{b};
    t0 = tic ();
    if (numel (B) == 1)
      D = Ds{B};
    else
      D = fit_stack (Ds(B), 1);
      D.s = sc(B(1));
    endif
    D.def = def;
    D.nch = numel (B);
    D.sc = sc(B);
    run = grow (D, nlobes, opt, t0);
    for k = 1:nlobes
      P = fit_phys ("split", D, run.us{k});
      amp = [1, 2 + (0:k-1) * (1 + numel (def.shape))];
      P(amp,:) .*= sc(B);
      Ps{k}(:,B) = P;
    endfor
    info.time(B) = toc (t0);
    info.iterations(B) = run.iter;
    info.full_iterations(B) = run.iter;
    info.rejected(B) = run.rejected;
    info.converged(B) = run.cvg;
    info.enforced(B) = run.enforced;
    info.lobe_time(:,B) = run.ktime(:) * ones (1, numel (B));
    for i = 1:numel (B)
      traces{B(i)} = run.trace(:,[1 2 2+i]);
    endfor
    if (! run.cvg)
      warning ("lafortune:notConverged",
               "brdf_fit: channel(s) %s (%d lobes) did not converge in %d iterations; the parameters are finite but may not be optimal",
               mat2str (B), nlobes, opt.max_iter);
    endif
  endfor
  models = cellfun (@(P) __lafortune_model_pack__ (P, def), Ps, "uniformoutput", false);
  model = models{nlobes};
  fitted = false (1, 3);
  fitted(opt.channels) = true;
  F = @(m) material_eval (m, Srep.wi, Srep.wo);
  info = fit_errors (info, rep, names, F (model), cellfun (F, models(1:nlobes-1), "uniformoutput", false),
                     fitted, opt.weight);
  for c = opt.channels(:)'
    info.trace{c} = fit_trace (traces{c}, info.time(c), info.rmse(c),
                                strcmp (how, "exact") && n0 >= N);
  endfor
  for k = 1:nlobes
    info.albedo_lobes(k,:) = max (brdf_albedo (models{k}, fit_energy ()), [], 1);
  endfor
  info.albedo = info.albedo_lobes(nlobes,:);
  info.energy = info.albedo <= 1;
endfunction

## The growing fit of the data D (one channel, or several sharing shapes)
function run = grow (D, nlobes, opt, t0)
  nch = D.nch;
  G = rows (D.x);
  wl2 = reshape (D.wl .^ 2, G, nch);
  u = max (pi * sum (wl2 .* reshape (D.yl, G, nch), 1) ./ max (sum (wl2, 1), realmin), 0).';
  [obj, e0] = fit_objective (D, fit_eval (D, u));
  run = struct ("us", {cell(1, nlobes)}, "trace", [toc(t0), obj, e0], "iter", 0, "rejected", 0,
                "cvg", true, "enforced", false, "ktime", nan (1, nlobes));
  lm = struct ("tol", opt.tol, "max_iter", opt.max_iter, "bounds", true,
               "jacobian", "analytic");
  ns = numel (D.def.shape);
  for k = 1:nlobes
    ## a zero lobe keeps the k-1 lobe fit: the error never rises
    z = [zeros(nch, 1); log_or_lin(D.def, D.def.starts, 1)];
    best = struct ("u", [u; z], "obj", obj, "trace", zeros (0, 2 + nch), "cvg", true);
    if (obj > 0)
      starts = grow_starts (D, u, opt.tries);
      for i = 1:columns (starts)
        [uj, it, cv, T] = fit_lm (D, starts(:,i), lm, t0);
        run.iter += it;
        if (opt.energy)
          [uj, enf] = fit_energy (D, uj);
          run.enforced = run.enforced || enf;
        endif
        if (! guard_ok (D, uj))
          run.rejected += 1;
          continue;
        endif
        oj = fit_objective (D, fit_eval (D, uj));
        if (oj < best.obj)
          best = struct ("u", uj, "obj", oj, "trace", T, "cvg", cv);
        endif
      endfor
    endif
    u = best.u;
    obj = best.obj;
    run.cvg = best.cvg;
    run.trace = [run.trace; best.trace];
    run.us{k} = u;
    run.ktime(k) = toc (t0);
  endfor
endfunction

## The first value of each shape parameter's start grid, in fit coordinates
function q = log_or_lin (def, starts, i)
  q = cellfun (@(s) s(min (i, numel (s))), starts(:));
  logs = strcmp (def.scale(:), "log");
  q(logs) = log (q(logs));
endfunction

## Starts for one more lobe: every shape of the type's grid with its best
## amplitude per channel and change of rho_d (linear least squares on the
## linearised data, as fit_starts does for Lafortune lobes); the TRIES best
function U = grow_starts (D, u, tries)
  def = D.def;
  nch = D.nch;
  G = rows (D.x);
  grid = def.starts;
  [c{1:numel (grid)}] = ndgrid (grid{:});
  Q = cell2mat (cellfun (@(x) x(:), c, "uniformoutput", false));
  fcur = fit_eval (D, u);
  rho = u(1:nch);
  obj = inf (rows (Q), 1);
  S = zeros (nch, rows (Q));
  Dd = zeros (nch, rows (Q));
  for i = 1:rows (Q)
    g = def.lobe (D.x, Q(i,:));
    if (! all (isfinite (g)) || ! any (g > 0))
      continue;
    endif
    F = fcur;
    for ch = 1:nch
      r = (ch-1)*G+1:ch*G;
      w = D.wl(r) .^ 2;
      res = D.yl(r) - fcur(r);
      S1 = sum (w); Sr = sum (w .* res); Sg = sum (w .* g); Sgg = sum (w .* g .^ 2);
      Sgr = sum (w .* g .* res);
      dt = S1 * Sgg - Sg ^ 2;
      s = (S1 * Sgr - Sg * Sr) / dt;
      d = (Sr - s * Sg) / S1;
      if (! (dt > 0 && s > 0 && d >= -rho(ch) / pi))
        s = max (Sgr / max (Sgg, realmin), 0);
        d = 0;
      endif
      S(ch,i) = s;
      Dd(ch,i) = d;
      F(r) += d + s * g;
    endfor
    obj(i) = fit_objective (D, F);
  endfor
  ok = find (isfinite (obj) & any (S > 0, 1).');
  [~, o] = sort (obj(ok));
  ok = ok(o(1:min (tries, numel (o))));
  U = zeros (numel (u) + nch + numel (def.shape), numel (ok));
  logs = strcmp (def.scale, "log");
  for i = 1:numel (ok)
    q = Q(ok(i),:);
    q(logs) = log (q(logs));
    U(:,i) = [max(rho + pi * Dd(:,ok(i)), 0); u(nch+1:end); S(:,ok(i)); q(:)];
  endfor
endfunction

## The fit's model finite and at most 10 times the data's maximum on the
## data's groups
function ok = guard_ok (D, u)
  P = fit_phys ("split", D, u);
  ok = all (isfinite (u));
  for c = 1:D.nch
    g = __lafortune_model_core__ (D.def, P(:,c), D.x);
    ok = ok && all (isfinite (g)) && max (g) <= 10 * max (D.ymax(c), realmin);
  endfor
endfunction

## The groups the fit runs on: samples equal in X = [cos ti, cos to, wi.wo]
## (exact), or, with more than AUTO_GROUPS samples (or as "reduce" says), cells
## of an n x n x n grid over (sqrt (theta_h), theta_d, |cos ti - cos to|)
## (MERL's own spacing of theta_h: fine near the mirror direction) at the
## weighted mean of their samples' X, taken with cos ti <= cos to (every model
## here is reciprocal: f (wi, wo) = f (wo, wi))
function [j, xc, how] = groups (X, wt, reduce)
  AUTO_GROUPS = 20000;
  AUTO_GRID = 64;
  n = Inf;
  if (isnumeric (reduce))
    n = reduce;
  elseif (strcmp (reduce, "auto") && rows (X) > AUTO_GROUPS)
    n = AUTO_GRID;
  endif
  if (isinf (n))
    [j, xc] = fit_reduce (X, wt, Inf);
    how = "exact";
    return;
  endif
  G = brdf_geom (X);
  key = [floor(sqrt (acos (min (G.ch, 1)) / (pi/2)) * n), floor(acos (G.cd) / (pi/2) * n), ...
         floor(abs (X(:,1) - X(:,2)) * n)];
  [~, ~, j] = unique (min (key, n - 1), "rows");
  Xs = [min(X(:,1), X(:,2)), max(X(:,1), X(:,2)), X(:,3)];
  W = accumarray (j, wt);
  xc = [accumarray(j, wt .* Xs(:,1)), accumarray(j, wt .* Xs(:,2)), accumarray(j, wt .* Xs(:,3))] ./ W;
  how = sprintf ("grid %d", n);
endfunction
