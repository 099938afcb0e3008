## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{run} =} fit_grow (@var{D}, @var{R}, @var{nlobes}, @var{opt}, @var{G}, @var{p0}, @var{t0})
## Fit one channel, or several sharing their lobes' shapes (@code{D.nch} >
## 1, fit_stack), of any model type (private; fit_driver's one loop).
## @var{D} is the data in scaled units (fit_data; @code{D.def} the type,
## whose @code{coords} gives the fit's coordinates), @var{R} a coarser
## grouping of the same data for screening starts (or @var{D} itself),
## @var{G} the type's acceptance set (@code{coords ("region")}).  With a
## start @var{p0} (not empty), one Levenberg-Marquardt run from it; else
## lobes are added one at a time from the type's candidate starts
## (@code{coords ("starts")}), each run by fit_lm and kept if the type's
## guard (@code{coords ("guard")}) accepts it, or its repair (@code{coords
## ("repair")}: the lobes scaled down to the guard's bound, with the fit's
## rho_d or the previous one; a repaired result does not end the search),
## and the objective is lower:
## a zero lobe (@code{coords ("zero")}) keeps the previous error, so more
## lobes never fit worse.  The type's policy (@code{def.grow}) says how the
## starts are tried: @code{screen} (the first @code{opt.tries} get a few
## iterations on @var{R} and are ranked by the result, and a warm-up on
## @var{R} when the type's starts ask for one) and @code{first} (the first
## accepted start ends the search; else every start is run and the best
## kept).  With @code{opt.energy}, a result whose albedo exceeds 1 is
## refitted under that constraint (fit_energy).
##
## @var{run}: @code{ps} (cell, per lobe count, fit coordinates),
## @code{ktime} (seconds from @var{t0} until each lobe count was done),
## @code{iter} (every iteration), @code{full_iter} (those on @var{D}),
## @code{cvg}, @code{rejected}, @code{enforced} and @code{trace}: rows
## [seconds, objective, rmse per channel] of the evaluations on @var{D} of
## the kept runs.
## @end deftypefn
function run = fit_grow (D, R, nlobes, opt, G, p0, t0)
  run = struct ("ps", {cell(1, nlobes)}, "ktime", nan (1, nlobes), "iter", 0, "full_iter", 0,
                "cvg", true, "rejected", 0, "enforced", false, "trace", zeros (0, 2 + D.nch));
  if (! isempty (p0))
    [p, run.iter, run.cvg, run.trace] = fit_lm (D, p0, opt, t0);
    run.full_iter = run.iter;
    run.ps{nlobes} = p;
    return;
  endif
  ## 0 lobes: rho_d by weighted least squares (per channel)
  wl2 = reshape (D.wl .^ 2, [], D.nch);
  p = max (pi * sum (wl2 .* reshape (D.yl, [], D.nch), 1) ./ max (sum (wl2, 1), realmin), 0).';
  [obj, e0] = fit_objective (D, fit_eval (D, p));
  run.trace = [toc(t0), obj, e0];
  for k = 1:nlobes
    lobe = add_lobe (D, R, p, obj, opt, G, t0);
    p = lobe.p;
    obj = lobe.obj;
    run.trace = [run.trace; lobe.trace];
    run.iter += lobe.iter;
    run.full_iter += lobe.full_iter;
    run.rejected += lobe.rejected;
    run.enforced = run.enforced || lobe.enforced;
    run.cvg = lobe.cvg;
    run.ps{k} = p;
    run.ktime(k) = toc (t0);
  endfor
endfunction

## One more lobe on top of P (objective OBJ), as the type's policy says
## (see above).  From the first start on, a warm-up run on R (when the
## type's starts ask for one) and then a run to convergence on D.
function run = add_lobe (D, R, p, obj, opt, G, t0)
  WARMUP_TOL = 1e-4;
  coords = D.def.coords;
  pol = D.def.grow;
  run = struct ("p", [p; coords("zero", D)], "obj", obj, "trace", zeros (0, 2 + D.nch),
                "iter", 0, "full_iter", 0, "rejected", 0, "cvg", true, "enforced", false);
  if (! (obj > 0))
    return;
  endif
  [starts, warmup] = coords ("starts", D, p, opt, R);
  if (isempty (starts))
    return;
  endif
  ## a warm-up stops at a looser tolerance, as it only brings the start
  ## closer, and ends by leasqr's own test (fit_lm): its last iteration and
  ## the dampings that iteration tries are on the coarse grid, where they
  ## cost little, and ending it one iteration earlier can cost the run on D
  ## more iterations than it saves
  warm = opt;
  warm.tol = max (opt.tol, WARMUP_TOL);
  warm.flat = false;
  done = false (1, columns (starts));
  ntry = min (opt.tries, columns (starts));
  if (pol.screen && ntry > 1)
    screen = opt;
    screen.max_iter = min (opt.screen_iter, opt.max_iter);
    sobj = zeros (1, ntry);
    for i = 1:ntry
      [starts(:,i), it, done(i)] = fit_lm (R, starts(:,i), screen);
      run.iter += it;
      sobj(i) = fit_objective (R, fit_eval (R, starts(:,i)));
    endfor
    [~, so] = sort (sobj);
    starts(:,1:ntry) = starts(:,so);
    done(1:ntry) = done(so);
  endif
  for i = 1:columns (starts)
    ps = starts(:,i);
    if (warmup && ! done(i))
      [ps, it] = fit_lm (R, ps, warm);
      run.iter += it;
    endif
    [pj, it, cv, T] = fit_lm (D, ps, opt, t0);
    run.iter += it;
    run.full_iter += it;
    if (opt.energy)
      [pj, enf] = fit_energy (D, pj);
      run.enforced = run.enforced || enf;
    endif
    repaired = false;
    if (! coords ("guard", D, pj, G))
      pj = repair (D, pj, p, G);
      if (isempty (pj))
        run.rejected += 1;
        continue;
      endif
      repaired = true;
    endif
    oj = fit_objective (D, fit_eval (D, pj));
    if (oj < run.obj)
      run.p = pj; run.obj = oj; run.cvg = cv; run.trace = T;
    endif
    if (pol.first && ! repaired)
      break;
    endif
  endfor
endfunction

## The repair of the result PJ that the guard rejects (coords ("repair"):
## its lobes scaled down to the guard's bound), or of PJ with the previous
## rho_d (of P), which the fit traded for the lobe it had: the one of lower
## objective that the guard accepts; [] when there is none
function best = repair (D, pj, p, G)
  coords = D.def.coords;
  best = [];
  alt = pj;
  alt(1:D.nch) = p(1:D.nch);
  bo = Inf;
  for q = {coords("repair", D, pj), coords("repair", D, alt)}
    if (! isempty (q{1}) && coords ("guard", D, q{1}, G))
      o = fit_objective (D, fit_eval (D, q{1}));
      if (o < bo)
        best = q{1}; bo = o;
      endif
    endif
  endfor
endfunction
