## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{T}, @var{times}] =} scene_trace (@var{objs}, @var{scene}, @var{O}, @var{D}, @var{epsilon})
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
## @end deftypefn
function [T, times] = scene_trace (objs, scene, O, D, epsilon)
  t0 = tic ();
  hit = rt_intersect (objs, O, D, epsilon, Inf);
  h = find (hit.obj > 0);
  t_int = toc (t0);

  t0 = tic ();
  P = O(h,:) + hit.t(h) .* D(h,:);
  Vw = -D(h,:);
  [Ng, Ns] = hit_normals (objs, hit, h, P);
  flip = sum (Ng .* Vw, 2) < 0;
  Ng(flip,:) = -Ng(flip,:);
  Ns(flip,:) = -Ns(flip,:);
  bad = sum (Ns .* Vw, 2) <= 0;
  Ns(bad,:) = Ng(bad,:);
  lt = scene.light;
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
