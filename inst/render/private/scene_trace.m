## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {[@var{T}, @var{times}] =} scene_trace (@var{objs}, @var{scene}, @var{O}, @var{D}, @var{epsilon})
## @deftypefnx {} {[@var{T}, @var{times}] =} scene_trace (@dots{}, @var{k}, @var{env})
## Trace camera rays (@var{O}, @var{D} from @code{camera_rays}) through a
## scene prepared by @code{scene_setup}: what each sample sees and whether
## the light reaches it (private, for @code{rt_render} and
## @code{merl_scene}).
##
## Fields of @var{T}: @code{miss} (m x 1, the ray hits nothing); for the
## hits, indices @code{h} into the rays and, per hit, @code{Ns} (the shading
## normal turned toward the viewer: the interpolated vertex normal of a mesh
## that has normals, else the geometric one; a shading normal that still
## faces away from the viewer is replaced by the geometric one), @code{L}
## (unit, toward the light), @code{V} (unit, toward the viewer),
## @code{cosi} = Ns . L, @code{E} (numel (h) x 3 irradiance on a surface
## facing the light) and @code{lit} (the light is above the shading and the
## geometric surface, and no object blocks the shadow ray, which starts
## @var{epsilon} off the geometric surface); @code{nshadow}, the shadow rays
## traced.  @var{times} = [intersection, shadow rays, normals] in seconds.
##
## Under an environment light or a list of directional lights
## (@code{scene.light.type} @qcode{"environment"} or @qcode{"lights"}) the
## light of each hit comes from @code{light_samples} for the pixel samples
## @var{k} (@var{env}: @code{D}, the distribution of @code{env_dist}, and
## @code{ns}, samples per pixel sample; or, with @code{env.mis} true,
## @code{mis_samples}: the map's and the BRDF density's samples), and @var{T} has instead of
## @code{L}, @code{cosi}, @code{E} and @code{lit} the field @code{S}: one
## row per light sample that reaches a hit (above the shading and the
## geometric surface, its shadow ray unblocked), @code{own} (the hit,
## an index into @code{h}), @code{X} = [cos theta_i, cos theta_o, wi . wo]
## (what an isotropic material needs, @code{material_x}) and @code{w} (the
## weight: radiance over density times cos theta_i, or the light's
## irradiance times cos theta_i).
## @end deftypefn
function [T, times] = scene_trace (objs, scene, O, D, epsilon, k = [], env = [])
  t0 = tic ();
  hit = rt_intersect (objs, O, D, epsilon, Inf);
  h = find (hit.obj > 0)(:);           # a column, also for one ray
  t_int = toc (t0);

  t0 = tic ();
  P = O(h,:) + hit.t(h) .* D(h,:);
  Vw = -D(h,:);
  [Ng, Ns] = __lafortune_hit_normals__ (objs, hit, h, P);
  flip = sum (Ng .* Vw, 2) < 0;
  Ng(flip,:) = -Ng(flip,:);
  Ns(flip,:) = -Ns(flip,:);
  bad = sum (Ns .* Vw, 2) <= 0;
  Ns(bad,:) = Ng(bad,:);
  lt = scene.light;
  if (any (strcmp (lt.type, {"environment", "lights"})))
    t_nrm = toc (t0);
    [T, t_sh] = sample_lights (objs, scene, k, env, h, P, Ng, Ns, Vw, epsilon);
    T.miss = hit.obj == 0;
    T.h = h;
    T.Ns = Ns;
    T.V = Vw;
    times = [t_int, t_sh, t_nrm];
    return;
  endif
  E = double (lt.irradiance(:).') .* [1 1 1];
  if (strcmp (lt.type, "directional"))
    L = repmat (lt.direction(:).' / norm (lt.direction), numel (h), 1);
    E = repmat (E, numel (h), 1);
    dist = Inf (numel (h), 1);
  else
    L = lt.position(:).' - P;
    dist = sqrt (sum (L .^ 2, 2));
    L ./= dist;
    E = E ./ dist .^ 2;
  endif
  cosi = sum (Ns .* L, 2);
  lit = cosi > 0 & sum (Ng .* L, 2) > 0;
  t_nrm = toc (t0);

  t0 = tic ();
  il = find (lit);
  if (! isempty (il))
    sh = rt_intersect (objs, P(il,:) + epsilon * Ng(il,:), L(il,:), 0,
                       dist(il) - epsilon, true);
    lit(il(isfinite (sh.t))) = false;
  endif
  t_sh = toc (t0);
  T = struct ("miss", hit.obj == 0, "h", h, "Ns", Ns, "L", L, "V", Vw, "cosi", cosi,
              "E", E, "lit", lit, "nshadow", numel (il));
  times = [t_int, t_sh, t_nrm];
endfunction

## the light samples of the hits, their cosines and their shadow rays
function [T, t_sh] = sample_lights (objs, scene, k, env, h, P, Ng, Ns, Vw, epsilon)
  if (isfield (env, "mis") && env.mis)
    [L, wt, own] = mis_samples (env, k(h), scene.seed, Ns, Vw);
  else
    [L, wt, own] = light_samples (scene.light, env.D, k(h), env.ns, scene.seed);
  endif
  cosi = sum (Ns(own,:) .* L, 2);
  coso = sum (Ns(own,:) .* Vw(own,:), 2);
  ok = find (cosi > 0 & coso > 0 & sum (Ng(own,:) .* L, 2) > 0);
  t0 = tic ();
  nsh = numel (ok);
  if (! isempty (ok))
    o = own(ok);
    sh = rt_intersect (objs, P(o,:) + epsilon * Ng(o,:), L(ok,:), 0, Inf, true);
    ok = ok(! isfinite (sh.t));
  endif
  t_sh = toc (t0);
  X = [cosi(ok), coso(ok), sum(L(ok,:) .* Vw(own(ok),:), 2)];
  T = struct ("S", struct ("own", own(ok), "X", X, "w", wt(ok,:) .* cosi(ok)),
              "nshadow", nsh);
endfunction
