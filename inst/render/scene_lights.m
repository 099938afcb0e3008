## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{scene} =} scene_lights (@var{scene}, @var{K})
## @deftypefnx {lafortune} {[@var{scene}, @var{info}] =} scene_lights (@dots{})
## Replace a scene's environment light by @var{K} directional lights: the
## median cut of Debevec (2005).
##
## The lat-long map of @code{scene.light} (@code{scene_make} option
## @qcode{"light"}, @qcode{"environment"}) is cut into @var{K} rectangles of
## texels: the rectangle with the most light is cut in two along its longer
## side (in angle: its height, or its width times sin theta at its middle)
## where half of its light (luminance times solid angle) lies on each side,
## until there are @var{K}.  Each rectangle becomes one directional light
## toward its light's centroid, with the rectangle's irradiance (the sum
## over its texels of radiance times solid angle, per channel: the
## irradiance on a surface facing the light), so that the lights together
## carry the map's light.  The returned scene has @code{light.type}
## @qcode{"lights"} with fields @code{directions} (@var{K} x 3, unit, world)
## and @code{irradiance} (@var{K} x 3), which both renderers take:
## @code{rt_render} shades every hit with every light and traces a shadow
## ray to each, @code{pov_render} writes the lights into the POV-Ray scene.
##
## @var{info} has the fields @code{regions} (@var{K} x 4, first and last row
## and column of each rectangle), @code{energy} (the luminance irradiance
## per light) and @code{time}.  @var{K} must be an integer from 1 to the
## number of texels; a scene without an environment light gives
## @code{lafortune:badScene}.
##
## @example
## @group
## s = scene_make ("sphere", "light", "environment", "map", "sky", "size", 64);
## s16 = scene_lights (s, 16);
## size (s16.light.directions)          # 16 x 3
## m = struct ("rho_d", [0.5 0.4 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 20 20]);
## a = rt_render (s, m, "progress", false);     # sampled map
## b = rt_render (s16, m, "progress", false);   # 16 lights
## @end group
## @end example
## @seealso{scene_make, rt_render, pov_render}
## @end deftypefn
function [scene, info] = scene_lights (scene, K)
  if (nargin != 2)
    print_usage ();
  endif
  t0 = tic ();
  __lafortune_scene_check__ (scene, "scene_lights", "view");
  lt = scene.light;
  if (! strcmp (lt.type, "environment"))
    error ("lafortune:badScene",
           "scene_lights: SCENE must have an environment light (scene_make option \"light\", \"environment\"), got a %s light",
           lt.type);
  endif
  M = lt.map;
  [H, W, ~] = size (M);
  if (! (isnumeric (K) && isscalar (K) && isreal (K) && K >= 1 && K == fix (K) && K <= H * W))
    error ("lafortune:badOption",
           "scene_lights: K must be an integer from 1 to the map's %d texels", H * W);
  endif
  E = double (lt.irradiance(:).') .* [1 1 1];
  th0 = ((0:H-1).') / H * pi;
  th1 = ((1:H).') / H * pi;
  dw = (2 * pi / W) * (cos (th0) - cos (th1));          # texel solid angle, per row
  Y = __lafortune_luminance__ (M);
  e = Y .* dw;                                           # light per texel
  S = zeros (H + 1, W + 1);                              # summed-area table
  S(2:end,2:end) = cumsum (cumsum (e, 1), 2);
  box = @(r0, r1, c0, c1) S(r1+1,c1+1) - S(r0,c1+1) - S(r1+1,c0) + S(r0,c0);
  reg = zeros (K, 4);
  en = zeros (K, 1);
  reg(1,:) = [1 H 1 W];
  en(1) = box (1, H, 1, W);
  n = 1;
  done = false (K, 1);                                   # single texels, or no light
  while (n < K)
    cand = find (! done(1:n));
    if (isempty (cand))
      break;
    endif
    [~, i] = max (en(cand));
    i = cand(i);
    r = reg(i,:);
    nr = r(2) - r(1) + 1;
    nc = r(4) - r(3) + 1;
    if (nr * nc == 1 || en(i) <= 0)
      done(i) = true;
      continue;
    endif
    thm = (r(1) + r(2) - 1) / 2 / H * pi;
    byrow = nr > 1 && (nc == 1 || nr * pi / H >= nc * 2 * pi / W * sin (thm));
    if (byrow)
      c = box (r(1), r(1):r(2)-1, r(3), r(4));
      [~, j] = min (abs (c - en(i) / 2));
      q = r(1) + j - 1;
      a = [r(1) q r(3) r(4)];
      b = [q+1 r(2) r(3) r(4)];
    else
      c = box (r(1), r(2), r(3), r(3):r(4)-1);
      [~, j] = min (abs (c - en(i) / 2));
      q = r(3) + j - 1;
      a = [r(1) r(2) r(3) q];
      b = [r(1) r(2) q+1 r(4)];
    endif
    reg(i,:) = a;
    en(i) = box (a(1), a(2), a(3), a(4));
    n += 1;
    reg(n,:) = b;
    en(n) = box (b(1), b(2), b(3), b(4));
  endwhile
  if (n < K)
    error ("lafortune:badOption",
           "scene_lights: the map's light cannot be cut into %d parts (%d texels carry light)",
           K, nnz (e > 0));
  endif
  ## each region's direction (the centroid of its light) and irradiance
  [c, r] = meshgrid ((0:W-1) + 0.5, (0:H-1) + 0.5);
  th = r / H * pi;
  ph = c / W * 2 * pi - pi;
  [dir, R] = env_dirs (th(:), ph(:), lt.rotation);
  dir = reshape (dir, H, W, 3);
  D = zeros (K, 3);
  Ek = zeros (K, 3);
  for k = 1:K
    rr = reg(k,1):reg(k,2);
    cc = reg(k,3):reg(k,4);
    ek = e(rr,cc);
    for d = 1:3
      D(k,d) = sum (sum (dir(rr,cc,d) .* ek));
      Ek(k,d) = sum (sum (M(rr,cc,d) .* dw(rr)));
    endfor
    if (! (norm (D(k,:)) > 0))                           # no luminance: its middle
      D(k,:) = squeeze (dir(round (mean (rr)), round (mean (cc)), :)).';
    endif
  endfor
  D ./= sqrt (sum (D .^ 2, 2));
  D = D * R.';
  scene.light = struct ("type", "lights", "direction", [], "position", [],
                        "irradiance", Ek .* E, "directions", D);
  info = struct ("regions", reg, "energy", en, "time", toc (t0));
endfunction

%!test
%! ## the lights carry the map's light: a constant map's irradiance is 4 pi L
%! s = scene_make ("sphere", "size", 8, "light", "environment", "map", ones (32, 64, 3) * 0.5);
%! [t, info] = scene_lights (s, 16);
%! assert (t.light.type, "lights");
%! assert (size (t.light.directions), [16 3]);
%! assert (sum (t.light.irradiance), 4 * pi * 0.5 * [1 1 1], 1e-12);
%! assert (sqrt (sum (t.light.directions .^ 2, 2)), ones (16, 1), 1e-12);
%! ## equal light per region on a constant map (to a row of texels)
%! assert (max (info.energy) / min (info.energy) < 1.2);
%! ## every texel in exactly one region
%! cover = zeros (32, 64);
%! for k = 1:16
%!   r = info.regions(k,:);
%!   cover(r(1):r(2), r(3):r(4)) += 1;
%! endfor
%! assert (all (cover(:) == 1));

%!test
%! ## one bright texel: a light toward it, turned with the map
%! M = zeros (8, 16, 3) + 1e-3;
%! M(3, 13, :) = 100;                        # theta 56 deg, phi 135 deg (toward +x, +z)
%! s = scene_make ("sphere", "size", 8, "light", "environment", "map", M);
%! t = scene_lights (s, 4);
%! [~, i] = max (t.light.irradiance(:,1));
%! th = 2.5 / 8 * pi; ph = 12.5 / 16 * 2 * pi - pi;
%! d = [sin(th) * sin(ph), cos(th), -sin(th) * cos(ph)];
%! assert (t.light.directions(i,:) * d.' > 0.99);
%! s.light.rotation = 90;
%! t = scene_lights (s, 4);
%! [~, i] = max (t.light.irradiance(:,1));
%! R = [0 0 1; 0 1 0; -1 0 0];
%! assert (t.light.directions(i,:) * (d * R.').' > 0.99);

%!error <Invalid call> scene_lights (1)
%!error id=lafortune:badScene scene_lights (scene_make ("sphere", "size", 4), 4)
%!error id=lafortune:badOption scene_lights (scene_make ("sphere", "size", 4, "light", "environment", "map", ones (4, 8, 3)), 33)
%!error id=lafortune:badOption scene_lights (scene_make ("sphere", "size", 4, "light", "environment", "map", ones (4, 8, 3)), 2.5)

%!demo
%! ## the built-in sky as 16 lights, and a glossy sphere under both
%! s = scene_make ("sphere", "size", 96, "light", "environment", "map", "sky");
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);
%! a = rt_render (s, m, "progress", false);
%! b = rt_render (scene_lights (s, 16), m, "progress", false);
%! imshow (min ([a, b] / prctile (a(:), 99.5), 1) .^ (1/2.2));
%! title ("sampled map | 16 lights (median cut)");
