## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{S} =} merl_samples (@var{brdf})
## @deftypefnx {lafortune} {@var{S} =} merl_samples (@var{brdf}, @var{name}, @var{value}, @dots{})
## The whole valid hemisphere of a MERL material as a table of directions
## with quadrature weights, for a full (not only in-plane) fit.
##
## Every valid bin that meets the kept region (theta_i, theta_o <=
## @code{max_angle}) and whose grid point lies above the horizon becomes one
## sample, at its grid point (theta_h = (i/90)^2 pi/2, theta_d = j/90 pi/2,
## phi_d = k/180 pi, phi_h = 0), where the data were measured.
##
## @code{S.weight} (N x 1) makes a sum over the samples an integral over
## direction pairs: @code{sum (S.weight .* g)} approximates the integral of
## g (wi, wo) dwi dwo over the kept region when g is the value of a bin
## (exact for a function that is constant on each bin, such as the
## database's own nearest-bin lookup).  The weight of a bin is the measure
## of the set of direction pairs that the MERL lookup puts in that bin and
## that lie in the kept region.  In half/difference angles
##
## @example
## dwi dwo = 4 cos td sin th sin td  dth dph dtd dpd
## @end example
##
## (checked by Monte Carlo: pairs drawn uniformly over both hemispheres and
## binned with the reference reader's index fill the bins in proportion to
## these weights).  The Jacobian of the theta_h spacing is in the bin's
## theta_h range [(i/90)^2, ((i+1)/90)^2] pi/2; phi_h is integrated out
## (factor 2 pi) and the lookup's reciprocity fold adds the copy phi_d + pi
## (wi and wo swapped, factor 2 for the solid angle):
##
## @example
## w = 16 pi  int_bin cos td sin th sin td P dth dtd dpd
## @end example
##
## integrated numerically in theta_h and theta_d and exactly in phi_d (the
## kept phi_d of given theta_h, theta_d form one interval).  P = 1 for the
## solid angle, see @code{"measure"}.  Bins cut by the edge of the kept
## region count with the part inside, so for a material without missing
## samples the weights sum to the measure of the region,
## (2 pi (1 - cos max_angle))^2, to about 1e-6 (missing bins are dropped
## with their measure; at @code{max_angle} = 90 the bins whose grid point is
## on or below the horizon, 4e-4 of the total, are left out).  A sample's
## theta_i or theta_o may thus exceed @code{max_angle} by less than one bin
## (0.8 degrees at 80).
##
## Options:
##
## @table @code
## @item "max_angle"
## largest theta_i and theta_o kept, in degrees (default 80, as
## @code{merl_plane}).
## @item "measure"
## @code{"solid_angle"} (default): dwi dwo, P = 1.
## @code{"cosine"}: Ngan et al. 2005's measure, cos^2 theta_i dwi dwo, that
## is the weight of a squared residual times cos theta_i; as a bin holds
## both (wi, wo) and (wo, wi), P is the mean of cos^2 theta_i over the two,
## (cos^2 theta_i + cos^2 theta_o) / 2.  With it, the plain metric of
## @code{brdf_error} is Ngan et al.'s.
## @code{"projected"}: cos theta_i cos theta_o dwi dwo (the measure of
## reflected energy: the albedo of a Lambertian BRDF rho/pi is
## @code{sum (S.weight .* f) / pi} = rho).
## @item "max_samples"
## keep at most this many samples (default Inf), drawn in proportion to
## the weights: systematic sampling in bin order (stratified in theta_h,
## theta_d and phi_d; deterministic, the random generators are not touched).
## A bin whose weight is at least the sampling step T is kept with its own
## weight; every other drawn bin gets the weight T, so the weights still sum
## to the total.
## @item "views"
## true (default): attach the training views of the general fit,
## @code{S.views}: the material rendered on a small sphere under three
## directional lights, with the renders' traces.
## @code{lafortune_fit (S, n)} and @code{brdf_fit (S, type, n)} then fit
## the table with several weightings (log and cube root) and
## keep, for each lobe count, the fit that looks best in these views by
## FLIP (a fit of fewer lobes, padded with zero lobes, when that looks
## better): the recommended fit when the scene is not known.  Giving the
## fit a @qcode{"weight"} fits that weighting alone.  false: no views
## (the fit's default weighting is then log).
## @end table
##
## @var{S} has the fields of @code{merl_plane}'s result (@code{wi}, @code{wo},
## @code{rgb}, @code{theta_i}, @code{theta_o}, @code{name}) with
## @code{kind} = @code{"hemisphere"}, @code{index} (the bins' indices),
## @code{weight} (N x 1), @code{measure} (the measure's name) and
## @code{views} (struct array, empty without them: @code{scene},
## @code{cache}, @code{ref}).
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## S = merl_samples (brdf, "max_samples", 2e5);
## sum (S.weight)                    # (2 pi (1 - cosd (80)))^2 = 26.96
## e = brdf_error (lafortune_fit (S, 2), S, "log")
## [fit, info] = lafortune_fit (merl_samples (brdf), 3);  # the general fit
## info.weight                       # the weighting it chose
## @end group
## @end example
## @seealso{merl_plane, lafortune_fit, brdf_error}
## @end deftypefn
function S = merl_samples (brdf, varargin)
  if (nargin < 1)
    print_usage ();
  endif
  __lafortune_check_merl__ (brdf, "merl_samples");
  opt = __lafortune_parse_opts__ (varargin, "merl_samples",
                    struct ("max_angle", 80, "max_samples", Inf, "measure", "solid_angle",
                            "views", true));
  if (! isnumeric (opt.max_angle) || ! isscalar (opt.max_angle)
      || ! (opt.max_angle > 0 && opt.max_angle <= 90))
    error ("lafortune:badOption", "merl_samples: MAX_ANGLE must be a scalar in (0, 90] degrees");
  endif
  if (! isnumeric (opt.max_samples) || ! isscalar (opt.max_samples)
      || ! (opt.max_samples >= 1))
    error ("lafortune:badOption", "merl_samples: MAX_SAMPLES must be a scalar >= 1");
  endif
  measures = {"solid_angle", "cosine", "projected"};
  if (! ischar (opt.measure) || ! any (strcmp (opt.measure, measures)))
    error ("lafortune:badOption", "merl_samples: MEASURE must be one of %s",
           strjoin (measures, ", "));
  endif
  if (! ((islogical (opt.views) || isnumeric (opt.views)) && isscalar (opt.views)
         && any (opt.views == [0 1])))
    error ("lafortune:badOption", "merl_samples: VIEWS must be true or false, got %s",
           num2str (opt.views));
  endif
  w = merl_weights (double (opt.max_angle), opt.measure);
  idx = find (brdf.valid & w > 0);
  [wi, wo] = __lafortune_merl_grid__ (idx);
  up = wi(:,3) > 1e-12 & wo(:,3) > 1e-12;
  idx = idx(up); wi = wi(up,:); wo = wo(up,:);
  w = w(idx);
  if (numel (idx) > opt.max_samples)
    [k, w] = pps_draw (w, floor (opt.max_samples));
    idx = idx(k); wi = wi(k,:); wo = wo(k,:);
  endif
  wi ./= sqrt (sum (wi .^ 2, 2));
  wo ./= sqrt (sum (wo .^ 2, 2));
  name = "";
  if (isfield (brdf, "name"))
    name = brdf.name;
  endif
  S = struct ("wi", wi, "wo", wo, "rgb", brdf.data(idx,:),
              "theta_i", acosd (min (wi(:,3), 1)), "theta_o", acosd (min (wo(:,3), 1)),
              "name", name, "kind", "hemisphere", "index", idx,
              "weight", w, "measure", opt.measure, "views", []);
  if (opt.views)
    S.views = fit_views (brdf);
  endif
endfunction

## M of the units with weights W (positive column), drawn with probability
## proportional to W by systematic sampling in their order; units of weight
## >= the step are taken for certain with their own weight, the others get
## the step T = (remaining total) / (remaining draws): the sum is kept.
function [k, wk] = pps_draw (w, M)
  n = numel (w);
  sure = false (n, 1);
  do
    T = sum (w(! sure)) / (M - nnz (sure));
    add = ! sure & w >= T;
    sure |= add;
  until (! any (add) || nnz (sure) >= M)
  rest = find (! sure);
  R = M - nnz (sure);
  k = find (sure);
  wk = w(sure);
  if (R > 0 && ! isempty (rest))
    cs = cumsum (w(rest));
    T = cs(end) / R;
    at = ((1:R)' - 0.5) * T;
    j = min (lookup (cs, at) + 1, numel (rest));
    k = [k; rest(j)];
    wk = [wk; repmat(T, R, 1)];
  endif
  [k, o] = sort (k);
  wk = wk(o);
endfunction

%!shared b
%! b = struct ("data", zeros (1458000, 3), "valid", true (1458000, 1), "name", "flat");

%!test
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [10 10 10]);
%! bm = merl_synth (m, "missing", 70);
%! S = merl_samples (bm, "views", false);
%! assert (S.kind, "hemisphere");
%! assert (S.measure, "solid_angle");
%! assert (all (bm.valid(S.index)));
%! assert (size (S.weight), size (S.index));
%! assert (all (S.weight > 0));
%! ## grid points lie less than one bin beyond the kept region
%! assert (max ([S.theta_i; S.theta_o]) < 81);
%! ## the samples sit at the grid points: the model there equals the data
%! assert (S.rgb, lafortune_eval (m, S.wi, S.wo), -1e-9);
%! S2 = merl_samples (bm, "max_samples", 1000, "views", false);
%! assert (numel (S2.index), 1000);
%! assert (numel (unique (S2.index)), 1000);
%! assert (all (ismember (S2.index, S.index)));
%! assert (sum (S2.weight), sum (S.weight), 1e-12 * sum (S.weight));

%!test
%! ## the training views of the general fit: the material's renders and traces
%! bm = merl_synth (struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [10 10 10]));
%! S = merl_samples (bm, "max_samples", 2000);
%! assert (numel (S.views), 3);
%! for v = S.views
%!   assert (v.ref, rt_render (v.scene, bm, "progress", false), 1e-12);
%!   assert (any (v.ref(:) > 0));
%! endfor
%! S = merl_samples (bm, "max_samples", 2000, "views", false);
%! assert (isempty (S.views));

%!error <VIEWS must be true or false> merl_samples (b, "views", "yes")

%!test
%! ## total measure of the kept region: (2 pi (1 - cos max_angle))^2, also
%! ## after drawing max_samples (the weights are rescaled, the sum kept)
%! for a = [30 60 80]
%!   tot = (2 * pi * (1 - cosd (a))) ^ 2;
%!   S = merl_samples (b, "max_angle", a, "views", false);
%!   assert (sum (S.weight), tot, 1e-5 * tot);
%! endfor
%! for M = [1 5000 50000 numel(S.weight)-1]
%!   Sm = merl_samples (b, "max_samples", M, "views", false);
%!   assert (numel (Sm.weight), M);
%!   assert (sum (Sm.weight), sum (S.weight), 1e-10 * tot);
%! endfor
%! ## the cosine (Ngan) and projected measures: int cos^2 theta_i and
%! ## int cos theta_i cos theta_o over the region
%! c = cosd (80);
%! S = merl_samples (b, "measure", "cosine", "views", false);
%! assert (sum (S.weight), 2 * pi * (1 - c) * 2 * pi * (1 - c ^ 3) / 3, -1e-5);
%! S = merl_samples (b, "measure", "projected", "views", false);
%! assert (sum (S.weight), (pi * (1 - c ^ 2)) ^ 2, -1e-5);

%!test
%! ## hemispherical-hemispherical albedo of a Lambertian BRDF rho/pi over the
%! ## whole hemisphere: (1/pi) int f cos theta_i cos theta_o dwi dwo = rho
%! rho = [0.8 0.5 0.2];
%! m = struct ("rho_d", rho, "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! bl = merl_synth (m);
%! S = merl_samples (bl, "max_angle", 90, "measure", "projected", "views", false);
%! assert (sum (S.weight .* S.rgb) / pi, rho, 1e-3 * rho);
%! Sm = merl_samples (bl, "max_angle", 90, "measure", "projected", "max_samples", 20000, "views", false);
%! assert (sum (Sm.weight .* Sm.rgb) / pi, rho, 1e-3 * rho);

%!test
%! ## the weights are the bins' measure: quasi-random pairs, uniform over
%! ## both hemispheres (additive recurrence, no random state), binned with
%! ## the database's lookup, fill groups of bins in proportion to the weights
%! bi = b;
%! bi.data(:,1) = (1:1458000)';
%! S = merl_samples (b, "max_angle", 90, "views", false);
%! n = 4e5;
%! g = 1.1673039782614187;           # x^5 = x + 1: the R4 sequence
%! U = mod (0.5 + (1:n)' * g .^ -(1:4), 1);
%! si = sqrt (1 - U(:,1) .^ 2); so = sqrt (1 - U(:,2) .^ 2);
%! wi = [si .* cos(2*pi*U(:,3)) si .* sin(2*pi*U(:,3)) U(:,1)];
%! wo = [so .* cos(2*pi*U(:,4)) so .* sin(2*pi*U(:,4)) U(:,2)];
%! idx = merl_eval (bi, wi, wo)(:,1);
%! ## groups: 9 theta_h x 9 theta_d index blocks of 10 x 10
%! grp = @(k) floor (mod (floor ((k - 1) / 180), 90) / 10) + 9 * floor (floor ((k - 1) / 16200) / 10) + 1;
%! cnt = accumarray (grp (idx), 1, [81 1]) / n;
%! ex = accumarray (grp (S.index), S.weight, [81 1]) / (2 * pi) ^ 2;
%! ## 42 groups hold more than 0.5% each: within 1.2% of their measure
%! ## (dropping the cos theta_d factor would put them 61% off)
%! k = ex > 0.005;
%! assert (nnz (k) >= 40);
%! assert (max (abs (cnt(k) - ex(k)) ./ ex(k)) < 0.02);
%! assert (sum (ex), 1, 5e-4);   # 4e-4 left out: grid points below the horizon

%!test
%! ## the draw is deterministic and leaves the random generators alone
%! st = rand ("state"); sn = randn ("state");
%! S1 = merl_samples (b, "max_samples", 3000, "views", false);
%! S2 = merl_samples (b, "max_samples", 3000, "views", false);
%! assert (isequal (S1.index, S2.index) && isequal (S1.weight, S2.weight));
%! assert (isequal (rand ("state"), st) && isequal (randn ("state"), sn));
%! ## drawn in proportion to the measure: the mean weight per drawn sample
%! ## is the same in every theta_h block (up to certainty units)
%! S = merl_samples (b, "views", false);
%! ih = floor ((S1.index - 1) / 16200);
%! ihall = floor ((S.index - 1) / 16200);
%! share = accumarray (floor (ih / 10) + 1, 1, [9 1]) / 3000;
%! wshare = accumarray (floor (ihall / 10) + 1, S.weight, [9 1]) / sum (S.weight);
%! assert (share, wshare, 2e-3);

%!error <Invalid call> merl_samples ()
%!error id=lafortune:badOption merl_samples (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "max_samples", 0)
%!error <MAX_ANGLE must be a scalar in \(0, 90\]> merl_samples (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "max_angle", 95)
%!error <MEASURE must be one of> merl_samples (struct ("data", zeros (1458000, 3), "valid", true (1458000, 1)), "measure", "ngan")
%!error id=lafortune:badMerl merl_samples (struct ("data", 1))
