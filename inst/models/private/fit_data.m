## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{D} =} fit_data (@var{spec}, @var{c}, @var{j}, @var{xc}, @var{y})
## @deftypefnx {} {@var{D} =} fit_data (@var{spec}, @var{c}, @var{j}, @var{xc}, @var{y}, @var{s}, @var{pspec}, @var{yp}, @var{fname})
## @deftypefnx {} {@var{R} =} fit_data ("coarse", @var{D}, @var{jg}, @var{rep})
## One channel's data as the fit sees it (private): the sums of the metric
## @var{spec} (from metric_spec, the one definition of the metrics) for
## channel @var{c}, merged over the groups @var{j} (N x 1, from fit_reduce)
## at positions @var{xc} (G x 2, [a, c]); @var{y} (N x 1) is the channel's
## data in the units @var{spec} was made in.
##
## The metric is ss = sum_k w_k (t (f_k) - ty_k)^2 with per-sample weights w
## and transformed data ty (@code{spec.w}, @code{spec.ty}) and one transform
## t per channel, so for samples with equal (a, c), which share f,
## sum_k w_k (t (f) - ty_k)^2 = W (t (f) - tybar)^2 + sum_k w_k (ty_k -
## tybar)^2, W = sum_k w_k, tybar the w-weighted mean of ty: whatever the
## weights and data of the samples, the merged sum is exact.  @var{D} keeps
## @code{w} = sqrt (W), @code{ty} = tybar and the remainder @code{wsw}, so
## that fit_objective gives the metric's value; @code{n} (the metric's
## divisor), @code{t}, @code{dt}, @code{c} and @code{identity} (the
## transform), and for the linear amplitudes of the candidate starts the
## first-order weights w t'(y)^2 and their weighted mean data (@code{wl} =
## sqrt of their group sums, @code{yl}; for an identity transform, where ty
## is y, they are @code{w} and @code{ty}).  @code{ymax} is the largest |y|;
## @code{nch} = 1 channel (fit_stack makes several channels one problem).
##
## The one owner of the fit's data struct.  With @var{s} (the channel's
## scale: @var{y} is the data divided by it), @var{pspec} (the plain metric
## in the data's units) and @var{yp} (the data in those units), @var{D} is a
## fit's channel: @code{s}, @code{same} (the fit's metric is the plain one:
## its objective times s is the rmse) and otherwise @code{P}, the plain
## metric's groups, for the trace's rmse (fit_objective); a channel with no
## positive value warns @code{lafortune:negativeData} (in @var{fname}'s
## name).  With "coarse", the data @var{D} on the cells @var{jg} of a
## coarse grid (each group's cell), each cell represented by its group
## @var{rep} with the cell's summed weights: the objective on it is a
## quadrature of D's; unlike the cell's mean value at its mean (a, c), it
## has no bias where the model is curved within a cell, so its minimiser is
## closer to D's (fewer iterations on D after the warm-up).
## @end deftypefn
function D = fit_data (spec, c, j, xc, y, s, pspec, yp, fname)
  if (ischar (spec))
    D = coarse (c, j, xc);
    return;
  endif
  if (nargin > 5 && any (y < 0) && ! any (y > 0))
    warning ("lafortune:negativeData",
             "%s: channel %d has no positive value (a BRDF is non-negative); its fit is the zero model",
             fname, c);
  endif
  w = spec.w(:,c);
  ty = spec.ty(:,c);
  W = accumarray (j, w);
  D.x = xc;
  D.w = sqrt (W);
  D.ty = accumarray (j, w .* ty) ./ max (W, realmin);
  D.wsw = sum (w .* (ty - D.ty(j)) .^ 2);
  D.n = max (spec.norm, realmin);
  D.t = spec.t;
  D.dt = spec.dt;
  D.c = c;
  D.identity = spec.identity;
  if (spec.identity)
    ## the weights and data of the linear problem are the fit's own
    D.wl = D.w;
    D.yl = D.ty;
  else
    wl2 = w .* spec.dt (y, c) .^ 2;
    Wl = accumarray (j, wl2);
    D.wl = sqrt (Wl);
    D.yl = accumarray (j, wl2 .* y) ./ max (Wl, realmin);
  endif
  D.ymax = max (abs (y));
  D.nch = 1;
  D.ref = 1;
  if (nargin > 5)
    D.s = s;
    D.same = strcmp (spec.name, "plain");
    if (! D.same)
      D.P = fit_data (pspec, c, j, xc, yp);
    endif
  endif
endfunction

function R = coarse (D, jg, rep)
  R = D;
  R.x = D.x(rep,:);
  R.w = sqrt (accumarray (jg, D.w .^ 2));
  R.ty = D.ty(rep);
  R.wl = R.w;                          # (fit_data: wl is w for an identity)
  if (! D.identity)
    R.wl = sqrt (accumarray (jg, D.wl .^ 2));
  endif
  R.yl = D.yl(rep);
endfunction
