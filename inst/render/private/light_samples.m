## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{L}, @var{wt}, @var{own}] =} light_samples (@var{light}, @var{D}, @var{k}, @var{ns}, @var{seed})
## The light directions of the hits of the pixel samples @var{k} (0-based,
## as @code{sample_rays}) under an environment light or a list of
## directional lights (private, for @code{scene_trace}).  An environment
## light (@var{D} from @code{env_dist}) gets @var{ns} samples per pixel
## sample: the stratified points of @code{r2_points}, mapped through
## @code{env_sample}; so the samples
## depend on @var{k} and @var{seed} only, not on how many are traced at once.
## A list of lights gives every hit each light.  @var{L} (unit, world),
## @var{wt} (the radiance over the density divided by @var{ns}, or each
## light's irradiance) and @var{own} (the row of @var{k} each sample is
## for) have one row per sample.
## @end deftypefn
function [L, wt, own] = light_samples (light, D, k, ns, seed)
  m = numel (k);
  if (strcmp (light.type, "lights"))
    K = rows (light.directions);
    own = repmat (1:m, K, 1)(:);
    Ld = light.directions ./ sqrt (sum (light.directions .^ 2, 2));
    E = double (light.irradiance) .* [1 1 1];
    L = repmat (Ld, m, 1);
    wt = repmat (E, m, 1);
    return;
  endif
  ## the ns stratified points of each pixel sample (r2_points)
  [u, v] = r2_points (k, ns, seed);
  own = repmat (1:m, ns, 1)(:);
  [L, wt] = env_sample (D, u, v);
  wt /= ns;
endfunction
