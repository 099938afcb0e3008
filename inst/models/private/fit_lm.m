## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{p}, @var{iter}, @var{cvg}, @var{T}] =} fit_lm (@var{D}, @var{p0}, @var{opt}, @var{t0})
## One Levenberg-Marquardt run of leasqr on one channel's data @var{D}
## (from fit_data, or several channels' from fit_stack; private), from
## parameters @var{p0}, with the analytic Jacobian (or leasqr's dfdp),
## bounds rho_d >= 0 and 0 <= e <= 1e7 (and shared lobes' amplitudes >= 0;
## a physically based model's own, @code{fit_phys}) when
## @code{opt.bounds}, @code{opt.tol} and @code{opt.max_iter}.  When leasqr's
## handling of the bounds fails (its complementary pivoting can raise "not
## successful" on a degenerate step), the run is made without bounds and its
## result clamped to them; when that fails too, @var{p} is @var{p0} and
## @var{cvg} false.
##
## The run ends when leasqr's own test ends it (an iteration improves the
## sum of squares by less than @code{opt.tol} of it), or one iteration
## earlier, when the decrease that the Gauss-Newton step predicts is below
## half of that (MINPACK's predicted reduction, fit_recorder): leasqr then
## needs neither that iteration nor the five dampings it tries before it
## gives up.  With @code{opt.flat} false, only leasqr's own test.
##
## With @var{t0} (a @code{tic} value), every evaluation of the model is noted
## as a row [seconds since @var{t0}, objective, rmse] of @var{T}: the
## objective of @var{D} and the plain rmse in the data's units, one per
## channel (both from
## fit_objective); the caller decides whether the run counts.
## @end deftypefn
function [p, iter, cvg, T] = fit_lm (D, p0, opt, t0 = [])
  np = numel (p0);
  ftol = opt.tol;
  if (isfield (opt, "flat") && ! opt.flat)
    ftol = 0;                             # leasqr's own test only
  endif
  rec = fit_recorder (t0, ftol);
  F = @(xx, pp) model_fun (D, pp, rec);
  [lb, ub] = D.def.coords ("bounds", D, np);
  p0 = min (max (p0, lb), ub);
  options = struct ();
  if (opt.bounds)
    options.bounds = [lb ub];
  endif
  dp = 1e-3 * ones (np, 1);
  if (strcmp (opt.jacobian, "analytic"))
    dFdp = @(xx, f, pp, dpp, FF, varargin) model_jac (D, pp, f, rec);
  else
    dFdp = "dfdp";
  endif
  ## leasqr reads the global 'verbose'; it must be false here.  Leave the
  ## global space as it was found.
  had = any (strcmp ("verbose", who ("global")));
  global verbose;
  old = verbose;
  verbose = false;
  unwind_protect
    try
      [p, cvg, iter] = run_leasqr (rec, D.x, D.ty, p0, F, opt.tol, opt.max_iter, D.w, dp, dFdp,
                                   options);
    catch err
      ## leasqr's handling of bounds (complementary pivoting, cpiv_bard) can
      ## fail ("not successful") on a degenerate step: run without bounds,
      ## the result is clamped to them below; failing that, keep the start
      if (! isfield (options, "bounds"))
        rethrow (err);
      endif
      rec.rerun ();
      try
        [p, cvg, iter] = run_leasqr (rec, D.x, D.ty, p0, F, opt.tol, opt.max_iter, D.w, dp, dFdp,
                                     struct ());
      catch
        p = p0; cvg = false; iter = 0;
      end_try_catch
    end_try_catch
  unwind_protect_cleanup
    if (had)
      verbose = old;
    else
      clear -global verbose;
    endif
  end_unwind_protect
  p = real (p(:));
  if (! all (isfinite (p)))
    p = p0;
    cvg = false;
  endif
  if (opt.bounds)
    p = min (max (p, lb), ub);
  endif
  T = rec.T;
endfunction

## leasqr with the arguments ARGS, quiet (it prints " CONVERGENCE NOT
## ACHIEVED! " itself; lafortune_fit warns instead), ended early by the
## Jacobian's flat test (REC; see model_jac)
function [p, cvg, iter] = run_leasqr (rec, varargin)
  args = varargin;
  try
    ## (named outputs: evalc leaves an output undefined when the one before
    ## it is ignored with ~)
    [out, f, p, cvg, iter] = evalc ("leasqr (args{:})");
  catch err
    if (! strcmp (err.identifier, "lafortune:flatRun"))
      rethrow (err);
    endif
    p = rec.p;
    cvg = true;
    iter = rec.iter;
  end_try_catch
endfunction

## The model's values at P, transformed by the metric, for leasqr; the
## trace notes the objective and rmse (the transform is done once)
function ft = model_fun (D, p, rec)
  f = fit_eval (D, p);
  ft = f;
  if (! D.identity)
    ft = D.t (f, D.c);
  endif
  if (! isempty (rec.t0))
    [o, e] = fit_objective (D, f, ft);
    rec.add (o, e);
  endif
endfunction

## The Jacobian at P, where the model's (transformed) values are F; leasqr
## asks for it once per iteration, at its best point.  When REC finds that
## no step can improve the sum of squares by the run's tolerance any more,
## the run ends here (leasqr has no output function; the error is caught
## by run_leasqr, and P is the run's result).  A run with leasqr's own test
## only (REC's tolerance 0, a warm-up) skips the test
function J = model_jac (D, p, f, rec)
  [fm, J] = fit_eval (D, p);
  if (! D.identity)
    J .*= D.dt (fm, D.c);
  endif
  if (rec.tol > 0 && rec.flat (p, D.w, J, D.ty - f))
    error ("lafortune:flatRun", "fit_lm: no step can improve the fit by its tolerance");
  endif
endfunction
