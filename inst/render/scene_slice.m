## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{R} =} scene_slice (@var{scene}, @var{material}, @var{ti}, @var{to})
## @deftypefnx {lafortune} {@var{R} =} scene_slice (@var{scene}, @var{material}, @var{ti}, @var{to}, "pairs")
## @deftypefnx {lafortune} {[@var{R}, @var{gamma}] =} scene_slice (@dots{})
## Tabulate the 2-D slice of a material that a scene uses: radiance against
## the angles between the normal and the light and the normal and the viewer.
##
## With a directional light (unit direction L toward the light) and an
## orthographic camera (unit direction V toward the viewer), the angle gamma
## between L and V is the same at every surface point, so the radiance
## f(wi, wo) cos(theta_i) E of an isotropic BRDF depends only on
## ti = angle (N, L) and to = angle (N, V): the azimuth between wi and wo
## follows from cos gamma = cos ti cos to + sin ti sin to cos phi.
## @var{ti} and @var{to} are vectors of angles in radians; @var{R} is
## numel(ti) x numel(to) x 3.  Combinations no normal can reach (outside
## |ti - to| <= gamma <= ti + to) are filled by clamping cos phi to [-1, 1],
## i.e. with the nearest reachable configuration, so the table interpolates
## smoothly.  Where ti >= pi/2 or to >= pi/2 the radiance is 0.  With
## @code{"pairs"}, @var{ti} and @var{to} have the same length and @var{R} is
## numel(ti) x 3, one row per pair (ti(k), to(k)): no tensor grid.
##
## @var{material} is an analytic model (any type) or a MERL material (see
## @code{material_eval}).  This is the one tabulation both renderers use
## (@code{rt_render} and @code{pov_write_scene}).  Scenes with a point light
## or a perspective camera have no such slice: error
## @code{lafortune:sliceUnsupported}.
##
## @example
## @group
## scene = scene_make ("sphere");
## m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [30 30 30]);
## t = linspace (0, pi/2, 91);
## R = scene_slice (scene, m, t, t);
## imagesc (t, t, R(:,:,1)); xlabel ("angle (N, V)"); ylabel ("angle (N, L)");
## @end group
## @end example
## @seealso{rt_render, pov_write_scene, material_eval}
## @end deftypefn
function [R, gamma] = scene_slice (scene, material, ti, to, mode)
  if (nargin != 4 && nargin != 5)
    print_usage ();
  endif
  pairs = false;
  if (nargin == 5)
    if (! ischar (mode) || ! strcmp (mode, "pairs"))
      error ("lafortune:badOption", "scene_slice: the fifth argument may only be \"pairs\"");
    endif
    pairs = true;
  endif
  [L, V, E] = slice_geometry (scene);
  if (! isnumeric (ti) || ! isnumeric (to) || ! isreal (ti) || ! isreal (to)
      || ! isvector (ti) || ! isvector (to) || ! all (isfinite ([ti(:); to(:)])))
    error ("lafortune:badInput", "scene_slice: TI and TO must be real finite vectors of angles (radians)");
  endif
  if (isempty (__lafortune_material_kind__ (material)))
    error ("lafortune:badMaterial",
           "scene_slice: MATERIAL must be an analytic model (brdf_model) or a MERL material, got %s",
           class (material));
  endif
  ti = double (ti(:));
  to = double (to(:));
  cg = min (max (L * V', -1), 1);
  gamma = acos (cg);
  if (pairs)
    if (numel (ti) != numel (to))
      error ("lafortune:badInput", "scene_slice: with \"pairs\", TI and TO must have the same length");
    endif
    TI = ti; TO = to;
  else
    [TI, TO] = ndgrid (ti, to);
    TI = TI(:); TO = TO(:);
  endif
  [wi, wo] = __lafortune_slice_dirs__ (TI, TO, cg);
  ok = TI < pi/2 & TO < pi/2 & TI >= 0 & TO >= 0;
  f = zeros (numel (TI), 3);
  if (any (ok))
    f(ok,:) = material_eval (material, wi(ok,:), wo(ok,:));
  endif
  f .*= max (cos (TI), 0) .* E;
  if (pairs)
    R = f;
  else
    R = reshape (f, numel (ti), numel (to), 3);
  endif
endfunction

function [L, V, E] = slice_geometry (scene)
  __lafortune_scene_check__ (scene, "scene_slice", "view");
  if (! strcmp (scene.light.type, "directional") || ! strcmp (scene.camera.type, "orthographic"))
    error ("lafortune:sliceUnsupported",
           "scene_slice: a 2-D slice exists only for a directional light and an orthographic camera, got a %s light and a %s camera",
           scene.light.type, scene.camera.type);
  endif
  L = scene.light.direction(:)' / norm (scene.light.direction);
  cam = __lafortune_scene_camera__ (scene);
  V = -cam.f;
  E = scene.light.irradiance(:)';
  if (isscalar (E))
    E = E * [1 1 1];
  endif
endfunction

%!function s = __scene (L, V)
%!  s.light = struct ("type", "directional", "direction", L, "irradiance", 2);
%!  s.camera = struct ("type", "orthographic", "eye", 5 * V, "target", [0 0 0], "up", [0 1 0], "extent", 2);
%!endfunction

%!test
%! ## Lambertian: radiance = rho/pi cos(ti) E, independent of to
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! s = __scene ([0 0 1], [0 0.6 0.8]);
%! t = linspace (0, 1.5, 7);
%! R = scene_slice (s, m, t, t);
%! assert (R(:,:,2), 2 * 0.2 / pi * cos (t') * ones (1, 7), 1e-14);

%!test
%! ## against a direct evaluation at a real surface normal
%! m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -0.8 -0.5], "Cz", [1 0.9 0.7], "e", [30 10 3]);
%! L = [0.3 0.5 0.8]; L /= norm (L); V = [0 0 1];
%! s = __scene (L, V);
%! N = [0.2 0.3 0.9]; N /= norm (N);
%! ti = acos (N * L'); to = acos (N * V');
%! ## local frame at N
%! X = cross (N, [1 0 0]); X /= norm (X); Y = cross (N, X);
%! F = [X; Y; N];
%! ex = lafortune_eval (m, (F * L')', (F * V')') * (N * L') * 2;
%! assert (squeeze (scene_slice (s, m, ti, to))', ex, 1e-12);
%! ## and a MERL material through the same path
%! b = merl_synth (m);
%! assert (squeeze (scene_slice (s, b, ti, to))', merl_eval (b, (F * L')', (F * V')') * (N * L') * 2, -2e-3);  # bin edges

%!test
%! ## below the horizon: zero
%! m = struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3));
%! R = scene_slice (__scene ([0 0 1], [0 0 1]), m, [0 pi/2 2], [0 1.6]);
%! assert (R(:,:,1), [2/pi 0; 0 0; 0 0], 1e-15);   # E = 2

%!test
%! ## pairs: the diagonal of the tensor grid
%! m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -0.8 -0.5], "Cz", [1 0.9 0.7], "e", [30 10 3]);
%! s = __scene ([0.3 0.5 0.8] / norm ([0.3 0.5 0.8]), [0 0 1]);
%! t = linspace (0.1, 1.4, 5);
%! u = linspace (0.2, 1.2, 5);
%! R = scene_slice (s, m, t, u);
%! P = scene_slice (s, m, t, u, "pairs");
%! assert (size (P), [5 3]);
%! for k = 1:5
%!   assert (P(k,:), squeeze (R(k,k,:))', 1e-15);
%! endfor

%!error <Invalid call> scene_slice (1, 2, 3)
%!error id=lafortune:badScene scene_slice (1, 2, 3, 4)
%!error id=lafortune:sliceUnsupported scene_slice (scene_make ("sphere", "light", "point"), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), 0, 0)
%!error id=lafortune:sliceUnsupported scene_slice (scene_make ("sphere", "camera", "perspective"), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), 0, 0)
%!error id=lafortune:badMaterial scene_slice (struct ("light", struct ("type", "directional", "direction", [0 0 1], "irradiance", 1), "camera", struct ("type", "orthographic", "eye", [0 0 1], "target", [0 0 0], "up", [0 1 0], "extent", 2)), 1, 0, 0)
%!error id=lafortune:badScene scene_slice (struct ("light", struct ("type", "directional", "direction", [0 0 0], "irradiance", 1), "camera", struct ("type", "orthographic", "eye", [0 0 1], "target", [0 0 0], "up", [0 1 0], "extent", 2)), struct ("rho_d", [1 1 1], "Cxy", [], "Cz", [], "e", []), 0, 0)
