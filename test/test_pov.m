## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## test_pov: POV-Ray against the Octave raytracer, and what pov_write_scene
## leaves out.  Needs povray (3.7) and the exrread oct-file.
## Run: test ("test/test_pov.m")

%!shared m1, m3, rel
%! ## one sharp-ish lobe, and Lafortune et al.'s 3-lobe blue paint (REFERENCE.md)
%! m1 = struct ("rho_d", [0.05 0.1 0.2], "Cxy", [-1 -1 -1], "Cz", [0.95 0.95 0.95],
%!              "e", [60 60 60]);
%! m3 = struct ("rho_d", [0.3094 0.39667 0.70837] * pi,
%!              "Cxy", [0.870567 0.857255 0.670982; -0.451218 -0.406681 -0.477976;
%!                      -1.031545 -1.029426 -1.026588],
%!              "Cz", [0.803624 0.774290 0.586674; 0.023123 0.017625 0.227295;
%!                     0.706734 0.696530 0.687715],
%!              "e", [21.820103 18.597755 7.472717; 2.774499 2.581499 3.677653;
%!                    66.899060 63.767912 57.489181]);
%! m3.rho_d /= pi;
%! ## largest change relative to the image's peak
%! rel = @(a, b) max (abs (a(:) - b(:))) / max (abs (a(:)));

## ---- cross-check: pov_render against rt_render, one sample at pixel centres

%!test
%! sc = scene_make ("sphere", "size", [64 64], "spp", 1);
%! ref = rt_render (sc, m1, "jitter", false, "mode", "direct", "progress", false);
%! [img, info] = pov_render (sc, m1);
%! assert (size (img), size (ref));
%! assert (img_psnr (ref, img) >= 60);
%! ## and against rt_render's own default (its interpolated slice)
%! ref2 = rt_render (sc, m1, "jitter", false, "progress", false);
%! assert (img_psnr (ref2, img) >= 50);
%! ## not mirrored: the highlight is up and left, toward the light [-1 1 1]
%! [~, i] = max (img(:,:,2)(:));
%! [r, c] = ind2sub ([64 64], i);
%! assert (r < 32 && c < 32);

%!test
%! ## spheres on a plane, with cast shadows, three lobes
%! sc = scene_make ("spheres", "size", [64 64], "spp", 1);
%! ref = rt_render (sc, m3, "jitter", false, "mode", "direct", "progress", false);
%! img = pov_render (sc, m3);
%! assert (img_psnr (ref, img) >= 50);
%! ## the shadows are there: some lit-facing plane pixels are black in both
%! dark = all (ref < 1e-6 * max (ref(:)), 3) & all (img < 1e-6 * max (ref(:)), 3);
%! assert (nnz (dark) > 20);
%! ## and an emissive-only table (no shadows) would have failed: each shadow pixel
%! ## of rt_render is dark in POV-Ray too
%! sh = all (ref == 0, 3) & any (img > 1e-3 * max (ref(:)), 3);
%! assert (nnz (sh), 0);

%!test
%! ## every model type, through material_eval in both renderers: POV-Ray's
%! ## tables (one per term, model_terms) against rt_render's direct shading,
%! ## two lobes (broad and sharp) per model, on the sphere and the spheres
%! for sn = {"sphere", "spheres"}
%!   sc = scene_make (sn{1}, "size", [64 64], "spp", 1);
%!   prev = [];
%!   for t = {"blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley"}
%!     d = brdf_model (t{1});
%!     w = merge (d.hi(2) > 100, [30; 400], [0.2; 0.05]);     # exponent or roughness
%!     args = {"rho_d", [0.3 0.1 0.05], "ks", [0.5 0.4 0.3; 0.2 0.2 0.2], d.shape{1}, w};
%!     if (numel (d.shape) > 1)
%!       args(end+1:end+2) = {"F0", 0.1};
%!     endif
%!     m = brdf_model (t{1}, args{:});
%!     ref = rt_render (sc, m, "jitter", false, "mode", "direct", "progress", false);
%!     img = pov_render (sc, m);
%!     assert (img_psnr (ref, img) >= 50, "%s on %s: %.1f dB", t{1}, sn{1}, img_psnr (ref, img));
%!     assert (img_compare (ref, img).flip < 0.05, "%s on %s: FLIP %.3f", t{1}, sn{1},
%!             img_compare (ref, img).flip);     # the body too, which PSNR hardly sees
%!     assert (max (img(:)) > 0.1);
%!     if (! isempty (prev))
%!       ## the renders match far better than another model's picture does:
%!       ## the test can fail
%!       assert (img_psnr (ref, img) > img_psnr (ref, prev) + 10);
%!     endif
%!     prev = ref;
%!   endfor
%! endfor

%!test
%! ## a fit with a very sharp lobe over broad ones (a GGX fit of steel's scene
%! ## table has alpha 0.2, 0.07, 0.006): every term is kept and the body is
%! ## right.  lobe_tol measured terms against the table's peak, which the
%! ## sharp lobe puts 1e5 times above the body: the diffuse term and the
%! ## broad lobe were dropped, the body rendered at a tenth of its radiance,
%! ## at 57 dB (FLIP 0.88), which a PSNR test does not see
%! m = brdf_model ("ggx", "rho_d", 0.003, "ks", [0.015; 0.014; 0.045], "alpha", [0.3; 0.08; 0.007],
%!                 "F0", [0.2; 1; 1]);
%! sc = scene_make ("sphere", "size", [64 64], "spp", 1);
%! ref = rt_render (sc, m, "jitter", false, "mode", "direct", "progress", false);
%! [img, info] = pov_render (sc, m);
%! assert ([info.terms.kept], true (1, 4));
%! Y = sum (ref, 3);
%! Z = sum (img, 3);
%! body = Y > 0 & Y < 0.05 * max (Y(:));
%! assert (median (Z(body) ./ Y(body)), 1, 0.02);
%! assert (img_compare (ref, img).flip < 0.05);

%!test
%! ## the tabulation alone, without the SDL text (private pov_tables, called
%! ## from its folder): a GGX lobe's dense table is scene_slice's values over
%! ## cos ti on its grid, and its knots stay within the entries
%! g = brdf_model ("ggx", "ks", [1 0.5 0.2], "alpha", 0.08, "F0", 0.05);
%! sc = scene_make ("sphere", "size", [32 32], "spp", 1);
%! opt = struct ("entries", 64, "knots", "adaptive", "table_tol", 1e-3, "pad", 0.02);
%! here = pwd ();
%! unwind_protect
%!   cd (fullfile (fileparts (which ("pov_render")), "private"));
%!   cam = __lafortune_scene_camera__ (sc);
%!   L = sc.light.direction / norm (sc.light.direction);
%!   C = pov_tables ("inner_coord", false, L, -cam.f);
%!   gam = acos (L * -cam.f');
%!   D = pov_tables ("term_grid", sc, g, [0 1.4], [0 C.top], 129, [], opt, gam, C);
%!   R = pov_tables ("slice_grid", sc, g, D.ti, D.to, gam, C);
%!   [lo, hi] = pov_tables ("reach_bounds", D.ti, gam, C);
%!   in = D.to' > lo + 0.1 & D.to' < hi - 0.1;   # (near the edges: the C1 continuation)
%!   V = D.T .* cos (D.ti);
%!   assert (V(repmat (in, [1 1 3])), R(repmat (in, [1 1 3])), 1e-12 * max (R(:)));
%!   [T, io, Ki] = pov_tables ("term_knots", D, 1e-3 * D.max, D.max, opt);
%!   assert (numel (io) <= 64 && all (sum (Ki, 1) <= 64));
%!   assert (numel (io) > 8);                  # a sharp lobe needs entries
%! unwind_protect_cleanup
%!   cd (here);
%! end_unwind_protect

%!test
%! ## a sharp lobe (e = 2000): the entries go where it bends, 256 suffice
%! ms = struct ("rho_d", [0.05 0.05 0.05], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", 2000 * [1 1 1]);
%! sc = scene_make ("sphere", "size", [64 64], "spp", 1);
%! ref = rt_render (sc, ms, "jitter", false, "mode", "direct", "progress", false);
%! [img, info] = pov_render (sc, ms);
%! assert (img_psnr (ref, img) >= 50);
%! assert (max ([info.terms.outer]) <= 256 && max ([info.terms.inner]) <= 256);
%! ## evenly spaced entries do much worse with the same budget
%! [img_u, iu] = pov_render (sc, ms, "knots", "uniform", "entries", 128);
%! [img_a, ia] = pov_render (sc, ms, "entries", 128, "table_tol", 0);
%! assert (img_psnr (ref, img_a) > img_psnr (ref, img_u) + 6);
%! assert (ia.bytes < iu.bytes);

%!test
%! ## a very sharp lobe (e = 1e5, measured materials' fits reach it): in
%! ## (ti, to) it is a sliver along the edge of what normals reach, which 256
%! ## entries missed (54.9 dB, the highlight's pixel at the diffuse level);
%! ## the inner maps over theta_h = angle (N, H) hold it (measured 72.1 dB)
%! ms = struct ("rho_d", [0.05 0.05 0.05], "Cxy", -[1 1 1], "Cz", [1 1 1], "e", 1e5 * [1 1 1]);
%! sc = scene_make ("sphere", "size", [256 256], "spp", 1);
%! ref = rt_render (sc, ms, "jitter", false, "mode", "direct", "progress", false);
%! img = pov_render (sc, ms);
%! assert (img_psnr (ref, img) >= 65);
%! assert (max (img(:)), max (ref(:)), 0.01 * max (ref(:)));
%! assert (max (ref(:)) > 1.5 * 0.05 / pi);     # a pixel centre sees the lobe

%!test
%! ## a measured-like table: a specular peak 600 times the diffuse level in one
%! ## table (a MERL material).  Before, the tables put every entry at the peak
%! ## and the error allowed (relative to the peak) was about half the diffuse
%! ## level: this image was 5.3 times too bright (38.0 dB); specular-white-
%! ## phenolic's diffuse part 44% too dark at ti = 70 degrees
%! m = struct ("rho_d", [0.3 0.3 0.3], "Cxy", -1.0015 * [1 1 1], "Cz", 1.0015 * [1 1 1],
%!             "e", 3000 * [1 1 1]);
%! b = merl_synth (m, "name", "spike");
%! sc = scene_make ("sphere", "size", [128 128], "spp", 1, "jitter", false);
%! ref = rt_render (sc, b, "progress", false);
%! [img, info] = pov_render (sc, b);
%! lit = ref > 1e-3 * max (ref(:));
%! assert (max (ref(:)) > 300 * median (ref(lit)));
%! assert (median (abs (img(lit) - ref(lit)) ./ ref(lit)) < 0.01);   # measured: 0.0002
%! assert (mean (img(:)) / mean (ref(:)), 1, 0.05);                  # measured: 0.976
%! assert (img_psnr (ref, img) > 50);                                 # measured: 56.5 dB
%! assert (info.level < 0.1 * info.peak);

## ---- what is left out: the file shrinks, the image stays (1e-3 of the peak)

%!test
%! ## lobes below lobe_tol
%! sc = scene_make ("sphere", "size", [48 48], "spp", 1);
%! m = m1;
%! m.Cxy(2,:) = 0.03; m.Cz(2,:) = 0.03; m.e(2,:) = 4;      # (0.03 cos gamma)^4: ~1e-6 of the peak
%! [a, ia] = pov_render (sc, m, "lobe_tol", 0, "entries", 128);
%! [b, ib] = pov_render (sc, m, "entries", 128);
%! assert ([ia.terms.kept], [true true true]);
%! assert ([ib.terms.kept], [true true false]);
%! assert (ib.terms(3).contribution < 1e-4 && ib.terms(3).contribution > 0);
%! assert (ib.bytes < ia.bytes);
%! assert (rel (a, b) <= 1e-3);

%!test
%! ## angle ranges that visible surfaces do not reach: the middle of a sphere
%! sc = scene_make ("sphere", "size", [48 48], "spp", 1);
%! sc.camera.extent /= 3;
%! m = m1; m.e(:) = 20;                                  # accurate with 256 entries
%! [a, ia] = pov_render (sc, m, "crop", false);
%! [b, ib] = pov_render (sc, m);
%! assert (ib.bytes < 0.9 * ia.bytes);
%! assert (diff (ib.to_range) < 0.5 * diff (ia.to_range));
%! assert (rel (a, b) <= 1e-3);

%!test
%! ## geometry outside the view that casts no shadow into it
%! sc = scene_make ("spheres", "size", [48 48], "spp", 1);
%! k = numel (sc.objects);
%! sc.objects(k+1) = sc.objects(2);
%! sc.objects(k+1).center = [30 1 0];                   # far right, out of view
%! sc.objects(k+2) = sc.objects(2);
%! sc.objects(k+2).center = [0 0.5 20];                 # behind the camera
%! [V, F] = deal ([0 0 0; 1 0 0; 0 1 0; 1 1 0] + [0 5 -40], [1 2 3; 2 4 3]);
%! V = repmat (V, 50, 1) + kron ((0:49)', [0.1 0 0; 0.1 0 0; 0.1 0 0; 0.1 0 0]);
%! F = repmat (F, 50, 1) + 4 * reshape (repmat (0:49, 2, 1), [], 1);
%! sc.objects(k+3) = struct ("type", "mesh", "center", [], "radius", [], "point", [],
%!                           "normal", [], "vertices", V, "faces", F, "normals", []);
%! ## in view but off the frame, its shadow falls on the visible ground: kept
%! ldir = sc.light.direction;
%! sc.objects(k+4) = sc.objects(2);
%! sc.objects(k+4).center = [1 0 1.5] + 9 * ldir;      # over a free bit of ground
%! sc.objects(k+4).radius = 0.5;
%! [a, ia] = pov_render (sc, m1, "cull", false, "entries", 128);
%! [b, ib] = pov_render (sc, m1, "entries", 128);
%! assert (ia.objects, true (1, k + 4));
%! assert (ib.objects, [true(1, k), false, false, false, true]);
%! assert (ib.faces_dropped, 100);
%! assert (ib.bytes < ia.bytes - 2000);
%! assert (rel (a, b) <= 1e-3);
%! ## the shadowing sphere matters: without it the image changes
%! sc.objects(k+4) = [];
%! c = pov_render (sc, m1, "entries", 128);
%! assert (rel (b, c) > 1e-2);

%!test
%! ## mesh faces outside the view are dropped; the picture stays
%! sc = scene_make ("torus", "size", [40 40], "spp", 1, "resolution", [32 16]);
%! sc.camera.extent /= 2;                               # zoom in: part of the torus
%! [a, ia] = pov_render (sc, m1, "cull", false, "crop", false, "entries", 64);
%! [b, ib] = pov_render (sc, m1, "crop", false, "entries", 64);
%! assert (ib.faces_dropped > 0);
%! assert (ib.bytes < ia.bytes);
%! assert (rel (a, b) <= 1e-3);

## ---- pov_render's errors and options

%!error id=lafortune:povNotFound pov_render (scene_make ("sphere", "size", [8 8]), struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3)), "povray", "/nonexistent/povray")
%!error id=lafortune:povNotFound pov_render (scene_make ("sphere", "size", [8 8]), struct ("rho_d", [1 1 1], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3)), "povray", "no-such-povray-program")

%!test
%! ## a POV-Ray failure reports POV-Ray's message: a fake povray that fails like a parse error
%! d = tempname (); mkdir (d);
%! fake = fullfile (d, "povray");
%! fid = fopen (fake, "w");
%! fprintf (fid, "#!/bin/sh\necho \"File 'scene.pov' line 3: Parse Error: Expected 'object', } found instead\"\necho \"Fatal error in parser: Cannot parse input.\"\nexit 1\n");
%! fclose (fid);
%! chmod = system (sprintf ("chmod +x '%s'", fake));
%! unwind_protect
%!   sc = scene_make ("sphere", "size", [8 8]);
%!   try
%!     pov_render (sc, m1, "povray", fake);
%!     error ("no error");
%!   catch err
%!     assert (err.identifier, "lafortune:povFailed");
%!     assert (! isempty (strfind (err.message, "Parse Error: Expected 'object'")));
%!   end_try_catch
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!test
%! ## a real parse error: a wrapper breaks the scene, then runs povray
%! d = tempname (); mkdir (d);
%! fake = fullfile (d, "povray");
%! fid = fopen (fake, "w");
%! fprintf (fid, "#!/bin/sh\nsed -i 's/^camera {/camera { bogus_keyword/' scene.pov\nexec povray \"$@\"\n");
%! fclose (fid);
%! system (sprintf ("chmod +x '%s'", fake));
%! unwind_protect
%!   sc = scene_make ("sphere", "size", [8 8]);
%!   try
%!     pov_render (sc, m1, "povray", fake, "entries", 8);
%!     error ("no error");
%!   catch err
%!     assert (err.identifier, "lafortune:povFailed");
%!     assert (! isempty (strfind (err.message, "Parse Error")));
%!     assert (! isempty (strfind (err.message, "bogus_keyword")));
%!   end_try_catch
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!test
%! ## POV-Ray's worker threads not started in time (a loaded machine): the
%! ## run is tried again; twice here, then the real povray renders.  A fake
%! ## that always times out fails after three tries with POV-Ray's message
%! d = tempname (); mkdir (d);
%! fake = fullfile (d, "povray");
%! fid = fopen (fake, "w");
%! fprintf (fid, ["#!/bin/sh\nn=$(cat '%s/tries' 2>/dev/null || echo 0); echo $((n + 1)) > '%s/tries'\n", ...
%!               "if [ $n -lt 2 ]; then echo 'Timed out waiting for worker thread startup'; exit 1; fi\n", ...
%!               "exec povray \"$@\"\n"], d, d);
%! fclose (fid);
%! system (sprintf ("chmod +x '%s'", fake));
%! unwind_protect
%!   sc = scene_make ("sphere", "size", [8 8], "spp", 1);
%!   img = pov_render (sc, m1, "povray", fake, "entries", 8);
%!   assert (str2double (fileread (fullfile (d, "tries"))), 3);
%!   assert (img, pov_render (sc, m1, "entries", 8));
%!   unlink (fullfile (d, "tries"));
%!   fid = fopen (fake, "w");
%!   fprintf (fid, "#!/bin/sh\necho x >> '%s/tries'; echo 'Timed out waiting for worker thread startup'; exit 1\n", d);
%!   fclose (fid);
%!   try
%!     pov_render (sc, m1, "povray", fake, "entries", 8);
%!     error ("no error");
%!   catch err
%!     assert (err.identifier, "lafortune:povFailed");
%!     assert (! isempty (strfind (err.message, "worker thread startup")), err.message);
%!   end_try_catch
%!   assert (numel (strsplit (strtrim (fileread (fullfile (d, "tries"))), "\n")), 3);
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!test
%! ## several materials in one call: their POV-Ray runs at once, each image
%! ## the one a call of its own gives; with lights (frames), too
%! sc = scene_make ("sphere", "size", [16 12], "spp", 1);
%! m2 = m1; m2.e = m1.e / 4;
%! [img, info] = pov_render (sc, {m1, m2}, "entries", 16);
%! assert (iscell (img) && iscell (info) && numel (img) == 2);
%! assert (img{1}, pov_render (sc, m1, "entries", 16));
%! assert (img{2}, pov_render (sc, m2, "entries", 16));
%! assert (info{2}.time > 0 && info{2}.bytes > 0);
%! sl = scene_make ("sphere", "size", [16 12], "spp", 1, "light", "lights",
%!                  "light_direction", [0 0 1; 1 1 1], "irradiance", [1 1 1; 0.5 0.5 0.5]);
%! img = pov_render (sl, {m2, m1}, "entries", 16);
%! assert (img{1}, pov_render (sl, m2, "entries", 16));
%!error id=lafortune:badOption pov_render (scene_make ("sphere", "size", [8 8]), {})
%!error id=lafortune:badOption pov_render (scene_make ("sphere", "size", [8 8]), {m1, m1}, "keep", [tempname() ".pov"])

%!test
%! ## keep the scene file
%! sc = scene_make ("sphere", "size", [16 16], "spp", 1);
%! f = [tempname() ".pov"];
%! unwind_protect
%!   [img, info] = pov_render (sc, m1, "keep", f, "entries", 16);
%!   assert (info.file, f);
%!   assert (numel (fileread (f)), info.bytes);
%!   assert (strncmp (fileread (f), "// POV-Ray 3.7 scene", 20));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

%!test
%! ## anti-aliasing: POV-Ray's supersampling, close to rt_render's jittered spp
%! sc = scene_make ("sphere", "size", [32 32], "spp", 16);
%! ref = rt_render (sc, m1, "mode", "direct", "progress", false);
%! one = pov_render (sc, m1, "entries", 64);
%! aa = pov_render (sc, m1, "entries", 64, "antialias", 3);
%! assert (img_psnr (ref, aa) > img_psnr (ref, one));
%! assert (img_psnr (ref, aa) >= 35);

## ---- perspective camera: a third map level over gamma = angle (L, V)

%!test
%! ## four spheres on a plane, perspective, 2 lobes: direct shading in
%! ## rt_render at the pixel centres against POV-Ray's aoi/function tables
%! m2 = struct ("rho_d", [0.2 0.05 0.02], "Cxy", -[0.8 0.8 0.8; 0.6 0.6 0.6],
%!              "Cz", [0.8 0.8 0.8; 0.5 0.5 0.5], "e", [40 40 40; 5 5 5]);
%! sc = scene_make ("spheres", "size", [96 96], "spp", 1, "jitter", false,
%!                  "camera", "perspective");
%! ref = rt_render (sc, m2, "progress", false);
%! [img, info] = pov_render (sc, m2, "entries", 96);
%! assert (numel (info.gamma) >= 2);
%! assert ([info.terms.levels], numel (info.gamma) * [1 1 1]);
%! assert (issorted (info.gamma) && info.gamma(1) > 0 && info.gamma(end) < pi);
%! assert (img_psnr (ref, img) >= 50);
%! ## a looser gamma_tol: fewer levels, a smaller file
%! [~, info2] = pov_render (sc, m2, "entries", 96, "gamma_tol", 0.2);
%! assert (numel (info2.gamma) < numel (info.gamma));
%! assert (info2.bytes < info.bytes);

%!test
%! ## the orthographic sphere and the perspective one differ (the camera is
%! ## really perspective in the file) but each matches rt_render
%! sc = scene_make ("sphere", "size", [48 48], "spp", 1, "jitter", false,
%!                  "camera", "perspective");
%! ref = rt_render (sc, m1, "progress", false);
%! img = pov_render (sc, m1, "entries", 64);
%! assert (img_psnr (ref, img) >= 50);
%! sc.camera.type = "orthographic";
%! assert (img_psnr (pov_render (sc, m1, "entries", 64), img) < 40);

## ---- the Happy Buddha (../shared/data/meshes), when present

%!test
%! f = fullfile (fileparts (getenv ("MERL_PROXY_DIR")), "meshes", "happy-buddha.obj");
%! if (isempty (getenv ("MERL_PROXY_DIR")))
%!   f = "../shared/data/meshes/happy-buddha.obj";
%! endif
%! if (! exist (f, "file"))
%!   printf ("skipped: %s not found\n", f);
%! else
%!   m2 = struct ("rho_d", [0.2 0.05 0.02], "Cxy", -[0.8 0.8 0.8; 0.6 0.6 0.6],
%!                "Cz", [0.8 0.8 0.8; 0.5 0.5 0.5], "e", [40 40 40; 5 5 5]);
%!   ## the paper's size, deterministic: one ray through each pixel centre
%!   sc = scene_make ("mesh", "file", f, "size", "paper", "spp", 1, "jitter", false);
%!   ref = rt_render (sc, m2, "progress", false);
%!   img = pov_render (sc, m2, "antialias", false);
%!   assert (img_psnr (ref, img) >= 55);
%!   ## POV-Ray's anti-aliasing: the centre ray and rt_render's 2 x 2 grid
%!   sc.spp = 4;
%!   grid = rt_render (sc, m2, "progress", false);
%!   aa = pov_render (sc, m2, "antialias", 2);
%!   assert (img_psnr ((ref + 4 * grid) / 5, aa) >= 55);
%!   ## perspective, at half size
%!   sc = scene_make ("mesh", "file", f, "size", [256 128], "spp", 1, "jitter", false,
%!                    "camera", "perspective");
%!   assert (img_psnr (rt_render (sc, m2, "progress", false),
%!                     pov_render (sc, m2, "entries", 96)) >= 50);
%! endif
