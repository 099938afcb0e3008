## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {[@var{models}, @var{info}] =} fit_driver (@var{S}, @var{wt}, @var{n0}, @var{def}, @var{nlobes}, @var{opt}, @var{fname})
## The one fit driver (private), for every model type: lafortune_fit's and
## brdf_fit's engine.  @var{S} is the checked table (with a scene table's
## prior appended after row @var{n0}), @var{wt} its weights, @var{def} the
## type (model_def), @var{opt} the front's checked options, @var{fname} the
## front's name for messages.  Returns the models of 1 .. @var{nlobes}
## lobes of a growing fit (data units; the one fit, from a given start,
## otherwise) and the front's @var{info}.
##
## Every model returned is bounded on the whole hemisphere (the type's
## guard on @code{coords ("region")}): a growing fit keeps only lobes the
## guard accepts, or their repair; the one fit from a given start is
## checked when it ends: data that are zero give the zero model, a result
## the guard rejects is repaired, and one that cannot be repaired is the
## error @code{lafortune:unboundedFit}, which says where it explodes.
##
## What differs between the types is in their definitions: what the model
## sees of a pair of directions and how samples equal in it, or near, are
## grouped (@code{coords ("x")}, @code{coords ("groups")}, with a coarser
## grid for screening starts where the type screens), whether samples on or
## below the horizon enter the fit (@code{def.grow.below}), the acceptance
## set a growing fit is guarded by (@code{coords ("region")}), a given
## start (@code{coords ("start")}), the candidate starts and the policy of
## trying them (fit_grow), and the fitted parameters in the data's units
## (@code{coords ("params")}).  Samples of weight 0 are left out.  The data
## are divided by their largest magnitude per channel (one for all with
## @code{"color", "shared"}; fit_setup), so that the fit is scale invariant.
## Each channel, or the channels sharing lobes (fit_stack), is one problem
## for fit_grow.  The reported errors are brdf_error's (fit_errors), of the
## models as material_eval evaluates them, and a type that reports its
## albedo (@code{def.grow.albedo}: the physically based ones, brdf_albedo)
## gives it per lobe count.
## @end deftypefn

function [models, info] = fit_driver (S, wt, n0, def, nlobes, opt, fname)
  N = rows (S.wi);
  keep = wt > 0;
  if (! def.grow.below)
    keep = keep & S.wi(:,3) > 0 & S.wo(:,3) > 0;
  endif
  F = fit_setup (S, n0, keep, opt, fname);
  [Srep, rep, names, Sf, Ss, sc, fspec, pspec] = deal (F.Srep, F.rep, F.names, F.Sf, F.Ss, F.sc,
                                                     F.fspec, F.pspec);
  x = def.coords ("x", [], Sf);
  ## the coarse grid for starts and the acceptance set are for a growing
  ## fit only (from a given start, one run)
  grow = strcmp (opt.init, "grow") && isempty (opt.start);
  [j, xc, how, xr, jg, jrep] = def.coords ("groups", [], x, wt(keep), opt, grow);
  G = def.coords ("region", []);
  nan3 = nan (1, 3);
  info = struct ("nlobes", nlobes, "weight", opt.weight, "color", opt.color, "n", rows (x),
                 "groups", rows (xc), "reduce", how,
                 "rmse", nan3, "rel_rmse", nan3, "log_rmse", nan3, "cos_rmse", nan3,
                 "error", nan3,
                 "iterations", zeros (1, 3), "full_iterations", zeros (1, 3),
                 "rejected", zeros (1, 3), "converged", true (1, 3), "time", zeros (1, 3),
                 "trace", {cell(1, 3)}, "history", nan (nlobes, 3),
                 "lobe_time", nan (nlobes, 3));
  if (def.grow.albedo)
    info = cell2struct ([{def.type}; struct2cell(info)], [{"type"}; fieldnames(info)]);
    info.albedo = zeros (1, 3);
    info.albedo_lobes = zeros (nlobes, 3);
    info.energy = true (1, 3);
    info.enforced = false (1, 3);
  endif
  ## the parameters of each lobe count, one column per channel (a channel
  ## not fitted keeps the type's blank lobes)
  Ps = arrayfun (@(k) repmat ([0; repmat(def.blank(:), k, 1)], 1, 3), 1:nlobes,
                 "uniformoutput", false);
  if (strcmp (opt.color, "shared"))
    blocks = {opt.channels(:)'};
  else
    blocks = num2cell (opt.channels(:)');
  endif
  traces = cell (1, 3);
  for b = 1:numel (blocks)
    B = blocks{b};
    t0 = tic ();
    Ds = Rs = cell (1, numel (B));
    for i = 1:numel (B)
      c = B(i);
      Ds{i} = fit_data (fspec, c, j, xc, Ss.rgb(:,c), sc(c), pspec, Sf.rgb(:,c), fname);
      Ds{i}.def = def;
      Rs{i} = Ds{i};
      if (rows (xr) != rows (xc))
        Rs{i} = fit_data ("coarse", Ds{i}, jg, jrep);
      endif
    endfor
    if (numel (B) == 1)
      D = Ds{1};
      R = Rs{1};
    else
      D = fit_stack (Ds, F.iref);
      R = fit_stack (Rs, F.iref);
    endif
    D.sc = sc(B);
    p0 = def.coords ("start", D, opt, B, sc(B), nlobes);
    run = fit_grow (D, R, nlobes, opt, G, p0, t0);
    if (! grow)
      run.ps{nlobes} = bounded (D, run.ps{nlobes}, G, B, fname);
    endif
    for k = 1:nlobes
      if (! isempty (run.ps{k}))
        Ps{k}(:,B) = def.coords ("params", D, run.ps{k}, sc(B));
      endif
    endfor
    info.time(B) = toc (t0);
    info.iterations(B) = run.iter;
    info.full_iterations(B) = run.full_iter;
    info.rejected(B) = run.rejected;
    info.converged(B) = run.cvg;
    info.lobe_time(:,B) = run.ktime(:) * ones (1, numel (B));
    if (def.grow.albedo)
      info.enforced(B) = run.enforced;
    endif
    for i = 1:numel (B)
      traces{B(i)} = run.trace(:,[1 2 2+i]);
    endfor
    if (! run.cvg)
      warning ("lafortune:notConverged",
               "%s: channel(s) %s (%d lobes) did not converge in %d iterations; the parameters are finite but may not be optimal",
               fname, mat2str (B), nlobes, opt.max_iter);
    endif
  endfor
  models = cellfun (@(P) __lafortune_model_pack__ (P, def), Ps, "uniformoutput", false);
  model = models{nlobes};
  fitted = false (1, 3);
  fitted(opt.channels) = true;
  Fk = {};
  if (grow)
    Fk = cellfun (@(m) material_eval (m, Srep.wi, Srep.wo), models(1:nlobes-1), "uniformoutput", false);
  endif
  info = fit_errors (info, rep, names, material_eval (model, Srep.wi, Srep.wo), Fk, fitted,
                     opt.weight);
  ## (with a prior the trace's rows are on every fitted row: the last row is
  ## then the table's rmse)
  for c = opt.channels(:)'
    info.trace{c} = fit_trace (traces{c}, info.time(c), info.rmse(c),
                                strcmp (how, "exact") && n0 >= N);
  endfor
  if (def.grow.albedo)
    for k = 1:nlobes
      info.albedo_lobes(k,:) = max (brdf_albedo (models{k}, fit_energy ()), [], 1);
    endfor
    info.albedo = info.albedo_lobes(nlobes,:);
    info.energy = info.albedo <= 1;
  endif
  if (! grow)
    models = {model};
  endif
endfunction

## The one fit P (from a given start) of the channels B, bounded (see
## above): as it is, the zero model for zero data, its repair, or the error
function p = bounded (D, p, G, B, fname)
  coords = D.def.coords;
  if (coords ("guard", D, p, G))
    return;
  endif
  z = coords ("zero", D);
  if (all (D.ymax == 0))
    p = [zeros(D.nch, 1); repmat(z, (numel (p) - D.nch) / numel (z), 1)];
    return;
  endif
  r = coords ("repair", D, p);
  if (! isempty (r) && coords ("guard", D, r, G))
    p = r;
    return;
  endif
  [v, ti, to, c] = peak_at (D, p, G);
  side = "on the side of the light";
  if (to < 0)
    side = "on the mirror side";
  endif
  error ("lafortune:unboundedFit",
         "%s: the fit from the given start is unbounded on channel %d: %.3g times the data's largest value at theta_i = %g, theta_o = %g degrees (%s); expected at most 10 times it on the whole hemisphere: give another start, or let the fit grow (\"init\", \"grow\")",
         fname, B(c), v, ti, abs (to), side);
endfunction

## where on the plane of incidence G (fit_guard) the Lafortune model P of
## scaled data is largest against the data's maximum: the ratio V, the
## angles (degrees, TO < 0 on the mirror side) and the channel's index C
function [v, ti, to, c] = peak_at (D, p, G)
  v = -Inf; ti = to = NaN; c = 1;
  P = {p};
  if (D.nch > 1)
    P = shared_lobes ("split", p, D.ref, D.nch);
  endif
  for k = 1:numel (P)
    g = __lafortune_lafortune_core__ (P{k}, G.x(:,1), G.x(:,2)) / max (D.ymax(k), realmin);
    g(! isfinite (g)) = Inf;
    [m, i] = max (g);
    if (m > v)
      v = m; ti = G.ti(i); to = G.to(i); c = k;
    endif
  endfor
endfunction
