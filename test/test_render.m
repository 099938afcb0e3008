## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Integration tests of the Octave raytracer: scene_make, mesh_read, rt_bvh,
## rt_intersect, rt_render.  Run from the package root with
##   addpath ("inst"); test ("test/test_render.m")
## Every check compares against an independent computation (closed forms,
## analytic ray-sphere tests, a brute-force loop over triangles).

%!function s = lambert (rho)
%!  s = struct ("rho_d", rho, "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]);
%!endfunction

%!function [x, y] = pixel_offsets (s)
%!  ## orthographic image-plane offsets of the pixel centres
%!  [c, r] = meshgrid (0:s.width-1, 0:s.height-1);
%!  x = ((c + 0.5) / s.width - 0.5) * s.camera.extent * s.width / s.height;
%!  y = (0.5 - (r + 0.5) / s.height) * s.camera.extent;
%!endfunction

%!function [O, D] = ortho_rays (s)
%!  [x, y] = pixel_offsets (s);
%!  f = s.camera.target - s.camera.eye; f /= norm (f);
%!  rt = cross (f, s.camera.up); rt /= norm (rt);
%!  up = cross (rt, f);
%!  O = s.camera.eye + x(:) .* rt + y(:) .* up;
%!  D = repmat (f, numel (x), 1);
%!endfunction

%!function [t, disc] = ray_sphere (O, D, c, r)
%!  ## nearest t > 0 of rays O + t D with a sphere (Inf if none)
%!  oc = O - c;
%!  b = sum (oc .* D, 2);
%!  disc = b .^ 2 - sum (oc .^ 2, 2) + r ^ 2;
%!  t = Inf (rows (O), 1);
%!  h = disc > 0;
%!  t1 = -b - sqrt (max (disc, 0));
%!  t2 = -b + sqrt (max (disc, 0));
%!  t(h & t1 > 0) = t1(h & t1 > 0);
%!  k = h & t1 <= 0 & t2 > 0;
%!  t(k) = t2(k);
%!endfunction

%!function m = merl_material ()
%!  ## the MERL-format stand-in of the paper's material when present, else a
%!  ## synthetic MERL table of a Lafortune model
%!  ## MERL_PROXY_DIR is set by `make check`; by default ../shared/data/merl-proxy
%!  pd = getenv ("MERL_PROXY_DIR");
%!  if (isempty (pd))
%!    pd = fullfile (pwd, "..", "shared", "data", "merl-proxy");
%!  endif
%!  f = fullfile (pd, "green-metallic-paint.binary");
%!  if (exist (f, "file"))
%!    m = merl_read (f);
%!  else
%!    printf ("test_render: %s absent, using merl_synth\n", f);
%!    m = merl_synth (struct ("rho_d", [0.02 0.1 0.08], "Cxy", [-1 -1 -1], ...
%!                            "Cz", [0.9 0.9 0.9], "e", [60 60 60]));
%!  endif
%!endfunction

## ---------------------------------------------------------------- analytic

%!test
%! ## Lambertian sphere, directional light, pixel centres: closed form
%! ## rho/pi max (N.L, 0) E per pixel, both shading modes
%! s = scene_make ("sphere", "size", [32 32], "spp", 1, "irradiance", [2 1 0.5], ...
%!                 "light_direction", [1 0.5 0.7]);
%! rho = [0.8 0.5 0.2];
%! [x, y] = pixel_offsets (s);
%! in = x .^ 2 + y .^ 2 < 1;
%! N = [x(:), y(:), sqrt(max (1 - x(:) .^ 2 - y(:) .^ 2, 0))];
%! ex = reshape (max (N * s.light.direction', 0) .* in(:) .* rho / pi .* [2 1 0.5], 32, 32, 3);
%! assert (nnz (ex(:,:,1) > 0) > 200);
%! for mode = {"slice", "direct"}
%!   [img, info] = rt_render (s, lambert (rho), "jitter", false, "progress", false, ...
%!                            "mode", mode{1});
%!   assert (info.mode, mode{1});
%!   assert (img, ex, -1e-6);
%! endfor

%!test
%! ## perspective camera and point light (direct mode): the closed form with
%! ## the exact view rays and E = I / r^2
%! s = scene_make ("sphere", "size", [24 24], "spp", 1, "camera", "perspective", ...
%!                 "light", "point", "light_direction", [0.3 1 0.8]);
%! [img, info] = rt_render (s, lambert ([0.5 0.5 0.5]), "jitter", false, "progress", false);
%! assert (info.mode, "direct");
%! [c, r] = meshgrid (0:23, 0:23);
%! h = tand (s.camera.fov / 2);
%! D = [((c(:) + 0.5) / 24 - 0.5) * 2 * h, (0.5 - (r(:) + 0.5) / 24) * 2 * h, -ones(576, 1)];
%! D ./= sqrt (sum (D .^ 2, 2));
%! t = ray_sphere (repmat (s.camera.eye, 576, 1), D, [0 0 0], 1);
%! hit = isfinite (t);
%! P = s.camera.eye + t(hit) .* D(hit,:);
%! Lv = s.light.position - P;
%! r2 = sum (Lv .^ 2, 2);
%! ex = zeros (576, 1);
%! ex(hit) = 0.5 / pi * max (sum (P .* Lv, 2) ./ sqrt (r2), 0) .* s.light.irradiance(1) ./ r2;
%! assert (nnz (ex > 0) > 100);
%! assert (img(:,:,2)(:), ex, -1e-6);

## ---------------------------------------------------------------- shadows

%!test
%! ## spheres on a plane: a plane pixel is black exactly when the ray from its
%! ## plane point toward the light hits a sphere (analytic, independent of the
%! ## renderer), else it has the Lambertian closed form
%! s = scene_make ("spheres", "size", [48 64], "spp", 1);
%! img = rt_render (s, lambert ([0.6 0.6 0.6]), "jitter", false, "progress", false);
%! [O, D] = ortho_rays (s);
%! n = rows (O);
%! sph = s.objects(2:end);
%! ts = Inf (n, 1);
%! for k = 1:numel (sph)
%!   ts = min (ts, ray_sphere (O, D, sph(k).center, sph(k).radius));
%! endfor
%! tp = -O(:,2) ./ D(:,2);                  # plane y = 0
%! onplane = tp > 0 & tp < ts;
%! P = O(onplane,:) + tp(onplane) .* D(onplane,:);
%! L = s.light.direction;
%! shadow = false (rows (P), 1);
%! margin = Inf (rows (P), 1);
%! for k = 1:numel (sph)
%!   [t, disc] = ray_sphere (P, repmat (L, rows (P), 1), sph(k).center, sph(k).radius);
%!   shadow |= isfinite (t);
%!   margin = min (margin, abs (disc));
%! endfor
%! clear_ = margin > 1e-6;                  # skip rays grazing a sphere
%! v = img(:,:,1)(onplane);
%! assert (nnz (shadow & clear_) > 0.03 * nnz (onplane));
%! assert (nnz (! shadow & clear_) > 0.3 * nnz (onplane));
%! assert (all (v(shadow & clear_) == 0));
%! assert (v(! shadow & clear_), 0.6 / pi * L(2) * ones (nnz (! shadow & clear_), 1), -1e-6);

%!test
%! ## both sides: a plane whose normal points away from the viewer shades alike
%! s = scene_make ("spheres", "size", [24 32], "spp", 1);
%! a = rt_render (s, lambert ([0.3 0.3 0.3]), "jitter", false, "progress", false);
%! s.objects(1).normal = [0 -1 0];
%! b = rt_render (s, lambert ([0.3 0.3 0.3]), "jitter", false, "progress", false);
%! assert (a, b, 1e-15);

## ---------------------------------------------------------------- meshes

%!test
%! ## the built-in mesh scene against a brute-force loop over all triangles
%! s = scene_make ("torus", "size", [20 20], "spp", 1, "resolution", [10 6], ...
%!                 "background", [1 2 3]);
%! [O, D] = ortho_rays (s);
%! V = s.objects.vertices; F = s.objects.faces;
%! t = Inf (rows (O), 1); tri = zeros (rows (O), 1);
%! for j = 1:rows (F)                        # Moeller-Trumbore, one triangle at a time
%!   A = V(F(j,1),:); e1 = V(F(j,2),:) - A; e2 = V(F(j,3),:) - A;
%!   p = cross (D, repmat (e2, rows (D), 1), 2);
%!   det = p * e1';
%!   tv = O - A;
%!   u = sum (tv .* p, 2) ./ det;
%!   q = cross (tv, repmat (e1, rows (D), 1), 2);
%!   v = (sum (D .* q, 2)) ./ det;
%!   tt = (q * e2') ./ det;
%!   ok = abs (det) > 1e-14 & u >= 0 & v >= 0 & u + v <= 1 & tt > 0 & tt < t;
%!   t(ok) = tt(ok); tri(ok) = j;
%! endfor
%! assert (nnz (isfinite (t)) > 50 && nnz (! isfinite (t)) > 50);
%! hit = rt_intersect (s.objects, O, D);
%! assert (hit.t, t, 1e-9);
%! assert (hit.prim, tri);
%! img = rt_render (s, lambert ([0.5 0.5 0.5]), "jitter", false, "progress", false);
%! bg = reshape (img, [], 3) == [1 2 3];
%! assert (all (bg, 2), ! isfinite (t));

%!test
%! ## a mesh read from a binary PLY, smooth-shaded with its vertex normals:
%! ## close to the shading with the exact normals of the torus it samples,
%! ## much closer than flat shading.  Light at the camera: nothing seen is in
%! ## shadow, radiance = rho/pi (n . V).
%! [V, F, N] = mesh_torus ([48 24]);
%! f = [tempname() ".ply"];
%! fid = fopen (f, "w");
%! fprintf (fid, "ply\nformat binary_big_endian 1.0\nelement vertex %d\n", rows (V));
%! fprintf (fid, "property double x\nproperty double y\nproperty double z\n");
%! fprintf (fid, "property double nx\nproperty double ny\nproperty double nz\n");
%! fprintf (fid, "element face %d\nproperty list uchar int vertex_indices\nend_header\n", rows (F));
%! fwrite (fid, [V N]', "float64", 0, "ieee-be");
%! fwrite (fid, [3 * ones(1, rows (F)); F' - 1], "int32", 0, "ieee-be");
%! fclose (fid);
%! ## (the counts were written as int32: re-declare them so)
%! txt = fileread (f);
%! fid = fopen (f, "w");
%! fputs (fid, strrep (txt, "list uchar int", "list int int"));
%! fclose (fid);
%! s = scene_make ("mesh", "file", f, "size", [32 32], "spp", 1);
%! delete (f);
%! assert (s.objects.faces, F);
%! assert (s.objects.normals, N, 1e-12);
%! s.camera.eye = [0 3 4]; s.camera.target = [0 0 0];   # look down into the torus
%! s.light.direction = [0 0.6 0.8];
%! m = lambert ([0.5 0.5 0.5]);
%! img = rt_render (s, m, "jitter", false, "progress", false);
%! [O, D] = ortho_rays (s);
%! hit = rt_intersect (s.objects, O, D);
%! h = isfinite (hit.t);
%! k = 2 / 2.8;                             # scale applied by scene_make
%! q = (O(h,:) + hit.t(h) .* D(h,:)) / k;
%! c = [q(:,1), zeros(nnz (h), 1), q(:,3)];
%! n = q - c ./ sqrt (sum (c .^ 2, 2));       # exact normal of the torus R = 1
%! n ./= sqrt (sum (n .^ 2, 2));
%! ex = 0.5 / pi * abs (n * s.light.direction');
%! v = img(:,:,1)(h);
%! assert (nnz (h) > 200);
%! err_smooth = max (abs (v - ex));
%! s.objects.normals = [];
%! flat = rt_render (s, m, "jitter", false, "progress", false)(:,:,1)(h);
%! err_flat = max (abs (flat - ex));
%! assert (err_smooth < 0.015 * 0.5 / pi);    # measured 0.8 %, flat 10 %
%! assert (err_smooth < err_flat / 4);

## ---------------------------------------------------------------- sampling

%!test
%! ## the same seed gives the same image, another seed another image
%! s = scene_make ("spheres", "size", [16 24], "spp", 3, "seed", 5);
%! m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 20 20]);
%! a = rt_render (s, m, "progress", false);
%! rand ("state", 99);                      # the renderer seeds its own jitter
%! b = rt_render (s, m, "progress", false);
%! s.seed = 6;
%! c = rt_render (s, m, "progress", false);
%! assert (isequal (a, b));
%! assert (! isequal (a, c));
%! ## ... and leaves the caller's generator where it was
%! rand ("state", 1); x = rand (); rand ("state", 1);
%! rt_render (s, m, "progress", false);
%! assert (rand (), x);

%!test
%! ## more samples per pixel converge to the pixel average
%! s = scene_make ("sphere", "size", [12 12], "spp", 64);
%! hi = rt_render (s, lambert ([1 1 1]), "progress", false);
%! s.spp = 1;
%! lo = rt_render (s, lambert ([1 1 1]), "progress", false);
%! s.spp = 256; s.seed = 2;
%! ref = rt_render (s, lambert ([1 1 1]), "progress", false);
%! assert (img_psnr (ref, hi) > img_psnr (ref, lo) + 6);

## ---------------------------------------------------------------- slice

%!test
%! ## slice and direct shading agree for a Lafortune model and a MERL
%! ## material, and the slice is > 100 times smaller than a MERL table
%! m = struct ("rho_d", [0.05 0.1 0.2], "Cxy", [-1 -1 -1; -0.5 -0.5 -0.5], ...
%!             "Cz", [1 1 1; 0.6 0.6 0.6], "e", [400 400 400; 20 20 20]);
%! b = merl_material ();
%! for scn = {"sphere", "spheres"}
%!   s = scene_make (scn{1}, "size", [48 48], "spp", 1);
%!   for mat = {m, b}
%!     [a, ia] = rt_render (s, mat{1}, "progress", false);
%!     [d, id] = rt_render (s, mat{1}, "progress", false, "mode", "direct");
%!     assert ([ia.mode, id.mode], "slicedirect");
%!     assert (img_psnr (d, a) >= 50);
%!   endfor
%! endfor
%! assert (ia.material_bytes * 100 <= 1458000 * 3 * 8);
%! assert (id.material_bytes >= 1458000 * 3 * 8);

%!test
%! ## rt_render's help: for an analytic model the slice's image differs from
%! ## per-sample shading by less than 1e-4 of its peak (RMS), even for a
%! ## lobe of exponent 2000
%! m = struct ("rho_d", [0.05 0.1 0.2], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [2000 2000 2000]);
%! s = scene_make ("sphere", "size", [128 128], "spp", 1);
%! a = rt_render (s, m, "progress", false);
%! d = rt_render (s, m, "progress", false, "mode", "direct");
%! assert (sqrt (mean ((a(:) - d(:)) .^ 2)) < 1e-4 * max (d(:)));

## ---------------------------------------------------------------- bad input

%!error id=lafortune:unknownScene scene_make ("cornell")
%!error id=lafortune:badMaterial rt_render (scene_make ("sphere", "size", 8), struct ("rho", 1))
%!error id=lafortune:badMaterial rt_render (scene_make ("sphere", "size", 8), "green-metallic-paint")
%!error id=lafortune:meshReadNotFound scene_make ("mesh", "file", "/nonexistent/buddha.ply")

%!test
%! ## malformed mesh files: truncated, wrong counts, indices out of range
%! d = tempname (); mkdir (d);
%! hdr = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
%! cases = {"t.ply", [hdr "0 0 0\n1 0 0\n"], "lafortune:meshReadTruncated";
%!          "c.ply", [hdr "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n"], "lafortune:meshReadCount";
%!          "i.ply", [hdr "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"], "lafortune:meshReadIndex";
%!          "t.obj", "v 0 0 0\nv 1 0\n", "lafortune:meshReadFormat";
%!          "c.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "lafortune:meshReadCount";
%!          "i.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "lafortune:meshReadIndex";
%!          "x.off", "OFF\n3 1 0\n", "lafortune:meshReadFormat"};
%! for k = 1:rows (cases)
%!   f = fullfile (d, cases{k,1});
%!   fid = fopen (f, "w"); fputs (fid, cases{k,2}); fclose (fid);
%!   id = "";
%!   try
%!     scene_make ("mesh", "file", f);
%!   catch e
%!     id = e.identifier;
%!   end_try_catch
%!   assert (id, cases{k,3});
%! endfor
%! ## nothing was written next to the inputs
%! assert (numel (dir (d)) - 2, rows (cases));
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
