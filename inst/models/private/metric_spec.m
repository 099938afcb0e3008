## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{spec} =} metric_spec (@var{metric}, @var{S}, @var{fname})
## @deftypefnx {} {@var{spec} =} metric_spec (@var{metric}, @var{S}, @var{fname}, @var{delta})
## @deftypefnx {} {@var{names} =} metric_spec ()
## The one definition of the error metrics (private): what
## @code{brdf_error} reports and what a least-squares fitter
## (@code{lafortune_fit}) minimises.  Without arguments, the metrics' names
## (a cell).  @var{delta} (1 x 3), when given, is the table's delta below,
## already known (from another spec of the same table): it saves the
## weighted medians.
##
## Every metric is a weighted sum of squares over the samples of a table
## @var{S} (fields @code{rgb}, N x 3, @code{wi}, N x 3, and the optional
## ones below; a table as check_table returns it, which checks the weight),
## per channel c:
##
## @example
## ss(c) = sum_k w(k,c) (t(f(k,c)) - t(y(k,c)))^2,    y = S.rgb, f = the model
## @end example
##
## so a fitter minimises the residual r = sqrt (w) .* (t (f) - t (y)) with
## dr/df = sqrt (w) .* t'(f).  @var{spec} has the fields:
##
## @table @code
## @item name
## the metric's name.
## @item w
## N x 3, weights of the squared residuals: s .* m, with s = @code{S.weight}
## (1 when absent) and m the metric's own weight below.
## @item t, dt
## handles @code{t (f, c)} and @code{dt (f, c)}: the transform of channel
## c's model values (column, or a matrix of columns) and its derivative.
## @item identity
## true when t (f) = f (then dt = 1).
## @item ss
## handle @code{ss (f, c)}: channel c's weighted sum of squares above for
## the model values @var{f} (N x 1) at the samples.
## @item ty
## N x 3, the transformed data t (y).
## @item delta
## 1 x 3, delta per channel: 0.01 times the median of the channel's positive
## data (1 when it has none), as the fitter has always used; with
## @code{S.weight}, the median under those weights (so that a table drawn
## from another by @code{merl_samples}'s @code{"max_samples"} gets about the
## same delta).
## @item norm
## the sum of @code{S.weight} (N when absent); 1 for @code{"psnr"}.
## @item finish
## handle: @code{e = finish (ss)} with ss the 1 x 3 sums above.
## @item degree
## k such that e (c f, c y) = c^k e (f, y) for c > 0 (delta scales with the
## data).
## @end table
##
## The metrics (y+ = max (y, 0), f+ = max (f, 0)):
##
## @table @code
## @item "plain"
## t (f) = f, m = 1; e = sqrt (ss / norm) per channel (the weighted rms
## error; the paper's with unit weights).  Degree 1.
## @item "cosine"
## Ngan et al. 2005: the residual times cos theta_i, m = cos^2 theta_i
## (theta_i of S.wi, 0 below the horizon); e as plain.  Degree 1.  A table
## whose @code{S.measure} is already @code{"cosine"} is refused: use
## @code{"plain"} there.
## @item "relative"
## the residual divided by max (y, delta): m = 1 / max (y, delta)^2, t (f) = f;
## e as plain.  Degree 0.
## @item "log"
## after Loew et al. 2012, with their constant 1 replaced by delta:
## t (f) = log (f+ + delta), t'(f) = 1 / (f+ + delta) (0 for f < 0);
## log (f + delta) - log (y + delta) = log (1 + f/delta) - log (1 + y/delta).
## m = 1; e as plain.  Degree 0.
## @item "cuberoot"
## after Fores et al. 2012: t (f) = (f+ + delta)^(1/3),
## t'(f) = (f+ + delta)^(-2/3) / 3 (0 for f < 0); delta keeps t' finite at
## f = 0 and is negligible where f >> delta.  m = 1; e as plain.
## Degree 1/3.
## @item "psnr"
## image PSNR of a scene table (@code{S.kind} = @code{"scene"}), t (f) = f,
## m = @code{S.irradiance}^2, s = @code{S.weight} not normalised: the image
## MSE over pixels and channels is mean (ss) and
## e = 10 log10 (peak^2 / mean (ss)), a scalar.  Degree 0.
## @end table
##
## A scene table has the fields @code{kind} = @code{"scene"}, @code{wi},
## @code{wo} (N x 3), @code{rgb} (N x 3, the reference BRDF values),
## @code{weight} (N x 1, each sample's share of the image: the fraction of
## all the image's pixel samples that see this angle pair lit, so that
## sum (weight) <= 1), @code{irradiance} (N x 1 or N x 3: the light's
## irradiance times cos theta_i at the sample, so that radiance =
## BRDF .* irradiance) and optionally @code{peak} (the reference image's
## largest value, img_psnr's peak; default max (rgb .* irradiance)).  Then
## mean (ss) = sum_k weight_k mean_c ((f - y) irradiance)^2 is the image's
## MSE, exactly when every pixel sees one angle pair.
## @end deftypefn
function spec = metric_spec (metric, S, fname, delta)
  names = {"plain", "cosine", "relative", "log", "cuberoot", "psnr"};
  if (nargin == 0)
    spec = names;
    return;
  endif
  if (! ischar (metric) || ! any (strcmp (metric, names)))
    error ("lafortune:badMetric", "%s: METRIC must be one of %s", fname,
           strjoin (names, ", "));
  endif
  y = double (S.rgb);
  n = rows (y);
  s = ones (n, 1);
  if (isfield (S, "weight"))
    s = S.weight;                  # N x 1 double, checked by check_table
  endif
  if (nargin < 4 || isempty (delta))
    delta = ones (1, 3);
    for c = 1:3
      pos = y(:,c) > 0 & s > 0;
      if (any (pos))
        delta(c) = 0.01 * wmedian (y(pos,c), s(pos));
      endif
    endfor
  endif
  spec = struct ("name", metric, "w", [], "t", @(f, c) f, "dt", @(f, c) ones (size (f)),
                 "ty", y, "delta", delta, "norm", sum (s), "finish", @(ss) sqrt (ss / sum (s)),
                 "degree", 1, "peak", NaN, "identity", true, "ss", []);
  switch (metric)
    case "plain"
      spec.w = s .* ones (1, 3);
    case "cosine"
      if (isfield (S, "measure") && strcmp (S.measure, "cosine"))
        error ("lafortune:badMetric",
               "%s: S.weight is already Ngan's cosine measure (S.measure = \"cosine\"); use \"plain\"",
               fname);
      endif
      ci = max (double (S.wi(:,3)), 0);
      spec.w = (s .* ci .^ 2) .* ones (1, 3);
    case "relative"
      spec.w = s ./ max (y, delta) .^ 2;
      spec.degree = 0;
    case "log"
      spec.w = s .* ones (1, 3);
      spec.t = @(f, c) log (max (f, 0) + delta(c));
      spec.dt = @(f, c) (f >= 0) ./ (max (f, 0) + delta(c));
      spec.ty = log (max (y, 0) + delta);
      spec.degree = 0;
      spec.identity = false;
    case "cuberoot"
      spec.w = s .* ones (1, 3);
      spec.t = @(f, c) (max (f, 0) + delta(c)) .^ (1/3);
      spec.dt = @(f, c) (f >= 0) .* (max (f, 0) + delta(c)) .^ (-2/3) / 3;
      spec.ty = (max (y, 0) + delta) .^ (1/3);
      spec.degree = 1/3;
      spec.identity = false;
    case "psnr"
      if (! isfield (S, "kind") || ! strcmp (S.kind, "scene"))
        error ("lafortune:badMetric",
               "%s: \"psnr\" needs a scene table (S.kind = \"scene\", with fields weight, irradiance)",
               fname);
      endif
      if (! isfield (S, "weight") || ! isfield (S, "irradiance"))
        error ("lafortune:badSamples",
               "%s: a scene table needs the fields weight (N x 1) and irradiance (N x 1 or N x 3)",
               fname);
      endif
      E = S.irradiance;
      if (! (isnumeric (E) && isreal (E)) || ! any (columns (E) == [1 3]) || rows (E) != n
          || ! all (isfinite (E(:))) || any (E(:) < 0))
        error ("lafortune:badSamples",
               "%s: S.irradiance must be N x 1 or N x 3 (N = %d), finite and >= 0", fname, n);
      endif
      E = double (E) .* ones (1, 3);
      if (isfield (S, "peak"))
        peak = S.peak;
        if (! (isnumeric (peak) && isreal (peak) && isscalar (peak)) || ! (peak > 0 && peak < Inf))
          error ("lafortune:badSamples", "%s: S.peak must be a finite scalar > 0", fname);
        endif
      else
        peak = max (max (y, 0)(:) .* E(:));
        if (! (peak > 0))
          error ("lafortune:badSamples",
                 "%s: the scene table's reference radiance (rgb .* irradiance) is 0 everywhere: no peak",
                 fname);
        endif
      endif
      peak = double (peak);
      spec.w = s .* E .^ 2;
      spec.norm = 1;
      spec.finish = @(ss) 10 * log10 (peak ^ 2 / mean (ss));
      spec.degree = 0;
      spec.peak = peak;
  endswitch
  w = spec.w; t = spec.t; ty = spec.ty;
  spec.ss = @(f, c) sum (w(:,c) .* (t (f, c) - ty(:,c)) .^ 2);
endfunction

## median of Y under the weights S (> 0): the smallest y with at least half
## the weight at or below it, averaged with the next one at exactly half
## (equal weights: the ordinary median)
function m = wmedian (y, s)
  if (all (s == s(1)))
    ## equal weights: the ordinary median, in linear time
    n = numel (y);
    v = nth_element (y, floor ((n + 1) / 2):ceil ((n + 1) / 2));
    m = (v(1) + v(end)) / 2;
    return;
  endif
  [y, o] = sort (y);
  cs = cumsum (s(o));
  h = cs(end) / 2;
  k = find (cs >= h * (1 - 4 * eps), 1);
  m = y(k);
  if (abs (cs(k) - h) <= 4 * eps * cs(end) && k < numel (y))
    m = (y(k) + y(k+1)) / 2;
  endif
endfunction
