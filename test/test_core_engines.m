## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## The model's two engines give the same bits.  The private lafortune_core
## (the one evaluation of the model) calls the oct-file __lafortune_core__
## when it is built and otherwise does the arithmetic itself, in Octave; that
## Octave arithmetic is the reference.  Here the oct-file is hidden by taking
## its folder off the path, and values and Jacobians (lafortune_core itself,
## called from its private folder; lafortune_eval) and whole fits
## (lafortune_fit) are compared bit for bit, on ordinary, stiff and extreme
## models.  The same for pov_knots's refinement of one table and of many at
## once, which call the oct-files __pov_knots__ and __pov_knots_batch__ when
## they are built: the entries they choose on random tables (ties, NaN,
## masks) and whole POV-Ray scene files.  And
## rt_render's sums of the samples into the pixels (__rt_accum__), its
## shading from the slice table (__rt_slice__) and its draws from an
## environment map (__env_sample__), and the camera rays of its pixel
## samples (__rt_rays__): whole renders and renders from the trace cache.
## And the directions of the MERL bins (__merl_grid__) and of angle
## triples (__slice_dirs__).

%!function varargout = __octave_engine (fn, oct = "__lafortune_core__")
%!  ## FN () with the oct-file OCT off the path
%!  d = fileparts (which (oct));
%!  assert (! isempty (d), sprintf ("the oct-file %s is not built (make -C src)", oct));
%!  assert (! strcmp (d, fileparts (which ("lafortune_eval"))),
%!          "the oct-file shares its folder with the m-files; it cannot be hidden");
%!  old = path ();
%!  ## every path entry that is that folder (as given, maybe relative)
%!  dirs = strsplit (old, pathsep ());
%!  hide = dirs(strcmp (cellfun (@canonicalize_file_name, dirs, "UniformOutput", false),
%!                      canonicalize_file_name (d)));
%!  unwind_protect
%!    rmpath (hide{:});
%!    assert (exist (oct, "file"), 0);
%!    [varargout{1:nargout}] = fn ();
%!  unwind_protect_cleanup
%!    path (old);
%!  end_unwind_protect
%!  assert (exist (oct, "file"), 3);
%!endfunction

%!function [st, out] = __with_damaged (oct, lines)
%!  ## run LINES (a cell of Octave statements) in a fresh octave-cli with
%!  ## this path and a damaged oct-file OCT ahead of it
%!  junk = tempname (); mkdir (junk);
%!  scr = [tempname() ".m"];
%!  unwind_protect
%!    fid = fopen (fullfile (junk, [oct ".oct"]), "w");
%!    fwrite (fid, uint8 (1:100)); fclose (fid);
%!    fid = fopen (scr, "w");
%!    fprintf (fid, "path ('%s'); addpath ('%s');\n", path (), junk);
%!    fprintf (fid, "%s\n", lines{:});
%!    fclose (fid);
%!    [st, out] = system (sprintf ("octave-cli --no-gui --norc --no-history '%s' 2>&1", scr));
%!  unwind_protect_cleanup
%!    unlink (scr);
%!    confirm_recursive_rmdir (false, "local");
%!    rmdir (junk, "s");
%!  end_unwind_protect
%!endfunction

%!function [wi, wo] = __dirs (n)
%!  ## N direction pairs over the hemisphere, deterministic
%!  t = (1:n)' / (n + 1);
%!  ti = acos (1 - 0.98 * t); to = acos (1 - 0.98 * mod (7 * t, 1));
%!  pi_ = 2 * pi * mod (3 * t, 1); po = 2 * pi * mod (11 * t, 1);
%!  wi = [sin(ti) .* cos(pi_), sin(ti) .* sin(pi_), cos(ti)];
%!  wo = [sin(to) .* cos(po), sin(to) .* sin(po), cos(to)];
%!endfunction

%!function tf = __same_bits (a, b)
%!  tf = isequal (size (a), size (b)) && isequal (typecast (a(:), "uint64"), typecast (b(:), "uint64"));
%!endfunction

%!test
%! ## values on many rows (a render's light samples), which the oct-file
%! ## shares out over threads: still the Octave arithmetic, bit for bit, and
%! ## the ends of every thread's rows (odd counts) included
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   cd (fullfile (fileparts (which ("lafortune_eval")), "private"));
%!   rand ("state", 3);
%!   for n = [65535 131073 400001]
%!     sxy = 2 * rand (n, 1) - 1; sz = rand (n, 1);
%!     sxy(1:977:end) = NaN; sz(5:1013:end) = 0;
%!     p = [0.3; -1; 0.9; 40; -0.7; 0.8; 3e3; 0.2; 0.5; 1.5];
%!     fc = __lafortune_core__ (p, sxy, sz);
%!     fo = __octave_engine (@() __lafortune_lafortune_core__ (p, sxy, sz));
%!     assert (__same_bits (fc, fo), sprintf ("%d rows: the engines differ", n));
%!   endfor
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!test
%! ## values and Jacobians directly, bit for bit (NaN payloads and signed
%! ## zeros too): the oct-file against lafortune_core's Octave arithmetic
%! ## (the private function, called from its folder), on random and
%! ## extreme parameters and bases: NaN, Inf, 0, denormals, huge values,
%! ## e = 0, negative, huge exponents, bases above 1 (the cap at exp(300)),
%! ## no lobe, no rows
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   cd (fullfile (fileparts (which ("lafortune_eval")), "private"));
%!   rand ("state", 7);
%!   special = [NaN -Inf Inf 0 -0 realmin/4 -realmin 1e-300 1e300 -1e300 1 -1 2];
%!   evals = [0 -2 0.5 1 3 50 1e3 1e7 1e200 NaN Inf -Inf];
%!   n = 400;
%!   for trial = 1:60
%!     nl = mod (trial, 4);
%!     p = [rand * 2; (rand (3 * nl, 1) - 0.5) .* 10 .^ (4 * rand (3 * nl, 1) - 2)];
%!     p(4:3:end) = evals(randi (numel (evals), nl, 1));
%!     if (mod (trial, 3) == 0 && nl > 0)
%!       p(randi (numel (p))) = special(randi (numel (special)));
%!     endif
%!     m = n * (trial != 1);                      # one trial with no rows
%!     sxy = 2 * rand (m, 1) - 1; sz = rand (m, 1) .* (1 + (trial > 40));
%!     k = randperm (m, min (m, 20));
%!     sxy(k(1:end/2)) = special(randi (numel (special), numel (k(1:end/2)), 1));
%!     sz(k(end/2+1:end)) = special(randi (numel (special), numel (k(end/2+1:end)), 1));
%!     [fc, Jc] = __lafortune_core__ (p, sxy, sz);
%!     fc1 = __lafortune_core__ (p, sxy, sz);
%!     [fo, Jo] = __octave_engine (@() __lafortune_lafortune_core__ (p, sxy, sz));
%!     fo1 = __octave_engine (@() __lafortune_lafortune_core__ (p, sxy, sz));
%!     assert (__same_bits (fc, fo) && __same_bits (Jc, Jo) && __same_bits (fc1, fo1),
%!             sprintf ("trial %d, p = %s: the engines differ", trial, mat2str (p', 4)));
%!   endfor
%!   ## exactly at the cap (e log b = 300: the lobe is live there)
%!   [fc, Jc] = __lafortune_core__ ([0; 1; 0; 300], exp (1), 0);
%!   [fo, Jo] = __octave_engine (@() __lafortune_lafortune_core__ ([0; 1; 0; 300], exp (1), 0));
%!   assert (__same_bits (fc, fo) && __same_bits (Jc, Jo));
%!   assert (Jc(2) > 0);
%!   ## the Jacobian is finite where the lobe is capped, even for e = 1e200
%!   [~, J] = __octave_engine (@() __lafortune_lafortune_core__ ([0; 1; 0; 1e200], 2, 0));
%!   assert (J, [1/pi 0 0 0]);
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!test
%! ## values: ordinary, sharp, capped (exp(300)), e = 0, tiny bases,
%! ## retro-reflective lobes, no lobe
%! [wi, wo] = __dirs (3000);
%! wi(1,:) = wo(1,:) = [0 0 1];
%! wo(2,:) = [-wi(2,1:2) wi(2,3)];             # the mirror direction
%! z = zeros (1, 3);
%! M = {struct("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.9 -1.1], "Cz", [1 0.8 0.95], "e", [10 20 5]), ...
%!      struct("rho_d", z, "Cxy", [-1 -1 -1; 1 2 3], "Cz", [1 1 1; 0.5 0.5 0.5], "e", [1e4 1e6 1e7; 0 0.5 2]), ...
%!      struct("rho_d", [1 1 1], "Cxy", [-5 -50 -500], "Cz", [5 50 500], "e", [200 400 1e5]), ...
%!      struct("rho_d", z, "Cxy", [-1e-200 1e-200 0], "Cz", [1e-200 1e-200 1e-300], "e", [3 50 1]), ...
%!      struct("rho_d", [0.5 0 0.25], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3))};
%! for k = 1:numel (M)
%!   fc = lafortune_eval (M{k}, wi, wo);
%!   fo = __octave_engine (@() lafortune_eval (M{k}, wi, wo));
%!   assert (isequal (fc, fo), sprintf ("model %d: the engines differ", k));
%!   assert (all (isfinite (fc(:))));
%! endfor

%!test
%! ## whole fits, so Jacobians too: noisy 2-lobe data, 1 to 3 lobes, the plain
%! ## and the log metric, the grown and the plain start
%! warning ("off", "lafortune:notConverged", "local");
%! [wi, wo] = __dirs (2500);
%! m0 = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1.05; -0.6 -0.7 -0.5],
%!              "Cz", [1 0.95 1; 0.3 0.4 0.2], "e", [40 25 60; 3 4 2]);
%! S.wi = wi; S.wo = wo;
%! S.rgb = lafortune_eval (m0, wi, wo) .* (1 + 0.05 * sin (97 * (1:2500)'));
%! cases = {{2, "weight", "plain"}, {3, "weight", "log"}, {1, "init", "plain"}};
%! for k = 1:numel (cases)
%!   a = cases{k};
%!   [mc, ic] = lafortune_fit (S, a{:});
%!   [mo, io] = __octave_engine (@() lafortune_fit (S, a{:}));
%!   assert (isequal (mc, mo), sprintf ("case %d: the models differ", k));
%!   assert (isequal (ic.rmse, io.rmse) && isequal (ic.iterations, io.iterations),
%!           sprintf ("case %d: the fits differ", k));
%! endfor

%!test
%! ## a stiff fit: exact data of a sharp lobe (e = 2000), tiny values
%! warning ("off", "lafortune:notConverged", "local");
%! [wi, wo] = __dirs (2000);
%! m0 = struct ("rho_d", 1e-9 * [1 2 3], "Cxy", -1.001 * [1 1 1], "Cz", [1 1 1],
%!              "e", [2000 1500 2500]);
%! S.wi = wi; S.wo = wo; S.rgb = 1e-6 * lafortune_eval (m0, wi, wo);
%! [mc, ic] = lafortune_fit (S, 1);
%! [mo, io] = __octave_engine (@() lafortune_fit (S, 1));
%! assert (isequal (mc, mo));
%! assert (isequal (ic.rmse, io.rmse));

%!test
%! ## pov_knots (private) on one table: the entries with the oct-file
%! ## __pov_knots__ and with the Octave code are the same, on smooth, sharp,
%! ## tied (flat and repeated columns), masked and NaN tables
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   cd (fullfile (fileparts (which ("pov_render")), "private"));
%!   rand ("state", 3);
%!   x = sort ([0; rand(298, 1); 1]) * pi / 2;
%!   c = cos (x);
%!   sharp = exp (-((x - 0.3) / 0.01) .^ 2) + 0.01 * x;
%!   bumps = exp (-((x - [0.2 0.9 1.3]) / 0.05) .^ 2);
%!   flat = ones (300, 4);
%!   kinks = repmat (abs (x - 0.7), 1, 3);
%!   noisy = [rand(300, 2), (x > 1) .* 5];
%!   cases = {sharp, [x.^3, bumps], flat, kinks, noisy};
%!   some = rand (300, 1) > 0.3;
%!   masks = {true, some, (x > 0.2 & x < 1.2)};
%!   P = {};
%!   for i = 1:numel (cases)
%!     for j = 1:numel (masks)
%!       for tol = [1e-4 1e-2]
%!         for nmax = [8 40 256]
%!           G = cases{i};
%!           if (i == 5 && j == 2)
%!             G(17, 1) = NaN;
%!           endif
%!           P(end+1,:) = {G, masks{j} & true(size (G)), tol, nmax, sprintf("case %d, mask %d, tol %g, nmax %d", i, j, tol, nmax)};
%!         endfor
%!       endfor
%!     endfor
%!   endfor
%!   knots = @() arrayfun (@(r) pov_knots (x, P{r,1}, c, P{r,2}, P{r,3}, P{r,4}, "adaptive"),
%!                         1:rows (P), "uniformoutput", false);
%!   K1 = knots ();
%!   K0 = __octave_engine (knots);
%!   for r = 1:rows (P)
%!     assert (isequal (K1{r}, K0{r}), P{r,5});
%!   endfor
%!   assert (sum (cellfun (@nnz, K1)) > 1000);
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!test
%! ## pov_knots (private) on many tables at once (refine_batch): the entries
%! ## with the oct-file __pov_knots_batch__ and with the Octave code are the
%! ## same, on smooth, sharp, tied, masked and NaN tables, with room to
%! ## spare and without (the tables that run out keep their worst intervals,
%! ## and start again from an even base)
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   cd (fullfile (fileparts (which ("pov_render")), "private"));
%!   rand ("state", 5);
%!   n = 200;
%!   x = sort ([0; rand(n - 2, 1); 1]) * pi / 2;
%!   c = cos (x);
%!   B = 9;
%!   G = zeros (n, 2, B);                           # sums of random bumps
%!   for b = 1:B
%!     for j = 1:2
%!       for k = 1:4
%!         G(:,j,b) += rand () * exp (-((x - 1.5 * rand ()) / (0.02 + 0.3 * rand ())) .^ 2);
%!       endfor
%!     endfor
%!   endfor
%!   G(:,:,7) = 1;                                  # flat: ties everywhere
%!   G(:,:,8) = round (4 * G(:,:,8)) / 4;           # steps: repeated values
%!   G(31,1,9) = NaN;
%!   M = true (n, 2, B);
%!   M(1:20,:,2) = false;                           # a table that starts late
%!   M(:,:,6) = rand (n, 2) > 0.4;
%!   P = {};
%!   for tol = [1e-4 1e-2]
%!     for nmax = [8 12 24 256]
%!       P(end+1,:) = {tol, nmax};
%!     endfor
%!   endfor
%!   knots = @() cellfun (@(tol, nmax) pov_knots (x, G, c, M, tol, nmax, "adaptive"),
%!                        P(:,1), P(:,2), "uniformoutput", false);
%!   K1 = knots ();
%!   K0 = __octave_engine (knots, "__pov_knots_batch__");
%!   for r = 1:rows (P)
%!     assert (size (K1{r}), [n B]);
%!     assert (isequal (K1{r}, K0{r}), sprintf ("tol %g, nmax %d", P{r,:}));
%!   endfor
%!   ## the cases happen: tables at their room, and refined well under it
%!   cnt = cellfun (@(K) sum (K, 1), K1, "uniformoutput", false);
%!   assert (sum (cnt{2} == 12) >= 5);
%!   assert (all (cnt{8}(1:6) > 12 & cnt{8}(1:6) < 256));
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!test
%! ## whole POV-Ray scene files, with and without the oct-files: the same
%! ## bytes (a fit and a measured material's tables); without them merl_eval
%! ## warns that it uses its Octave arithmetic, as it should: not shown here
%! warning ("off", "lafortune:noOctFile", "local");
%! sc = scene_make ("sphere", "size", [32 16], "spp", 1);
%! m = struct ("rho_d", [0.05 0.1 0.2], "Cxy", [-1 -0.5 -0.7; -0.9 -0.6 -0.7],
%!             "Cz", [1 0.6 0.8; 0.9 0.5 0.7], "e", [400 30 5e3; 20 35 40]);
%! rp = merl_standin ("red-plastic");
%! for mat = {m, rp}
%!   f1 = [tempname() ".pov"];
%!   f0 = [tempname() ".pov"];
%!   unwind_protect
%!     pov_write_scene (sc, mat{1}, f1);
%!     __octave_engine (@() pov_write_scene (sc, mat{1}, f0));
%!     assert (isequal (fileread (f1), fileread (f0)));
%!   unwind_protect_cleanup
%!     for f = {f1, f0}
%!       if (exist (f{1}, "file"))
%!         unlink (f{1});
%!       endif
%!     endfor
%!   end_unwind_protect
%! endfor

%!test
%! ## an oct-file that does not load (here a damaged one ahead on the path):
%! ## one warning lafortune:noOctFile, then the Octave arithmetic, the same
%! ## values; in a fresh octave-cli, as lafortune_core remembers it
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -0.9 -1.1], "Cz", [1 0.8 0.95], "e", [10 20 5]);
%! [wi, wo] = __dirs (50);
%! f = lafortune_eval (m, wi, wo);
%! [st, out] = __with_damaged ("__lafortune_core__", {
%!   sprintf("m = struct ('rho_d', %s, 'Cxy', %s, 'Cz', %s, 'e', %s);",
%!           mat2str (m.rho_d, 17), mat2str (m.Cxy, 17), mat2str (m.Cz, 17), mat2str (m.e, 17)),
%!   sprintf("wi = %s; wo = %s; f = %s;", mat2str (wi, 17), mat2str (wo, 17), mat2str (f, 17)),
%!   "g1 = lafortune_eval (m, wi, wo); g2 = lafortune_eval (m, wi, wo);",
%!   "[~, id] = lastwarn (); printf ('same %d %d, %s\\n', isequal (g1, f), isequal (g2, f), id);"});
%! assert (st == 0, "%s", out);
%! assert (! isempty (strfind (out, "same 1 1, lafortune:noOctFile")), out);
%! assert (numel (strfind (out, "does not work")) == 1, "%s", out);


%!test
%! ## the physically based models' values for shading: material_x calls the
%! ## oct-file __model_core__ (model_value) when it is built; model_core's
%! ## Octave arithmetic is the reference.  Bit for bit, every type, on many
%! ## rows (the oct-file's threads) with a lobe of zero amplitude, grazing
%! ## and mirror rows, and through material_x, the renderers' shading
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   cd (fullfile (fileparts (which ("rt_render")), "private"));
%!   rand ("state", 5);
%!   n = 131073;
%!   ci = [rand(n - 3, 1) * 0.999 + 0.001; 1; 1e-3; 0.5];
%!   co = [rand(n - 3, 1) * 0.999 + 0.001; 1; 1e-3; 0.5];
%!   ph = [2 * pi * rand(n - 3, 1); 0; pi; pi];
%!   w = ci .* co + sqrt (1 - ci .^ 2) .* sqrt (1 - co .^ 2) .* cos (ph);
%!   X = [ci, co, w];
%!   for t = {"blinnphong", "ward", "cooktorrance", "ggx", "ashikhminshirley"}
%!     def = __lafortune_model_def__ (t{1});
%!     ns = numel (def.shape);
%!     q = zeros (ns, 3);
%!     for j = 1:ns
%!       lo = def.lo(j+1); hi = min (def.hi(j+1), 1e3);
%!       if (strcmp (def.scale{j}, "log"))
%!         q(j,:) = exp (log (lo) + [0.1 0.5 0.9] * (log (hi) - log (lo)));
%!       else
%!         q(j,:) = lo + [0.1 0.5 0.9] * (hi - lo);
%!       endif
%!     endfor
%!     p = [0.7; reshape([[0; 1.3; 0.2], q'].', [], 1)];
%!     a = __lafortune_model_core__ (def, p, X);
%!     b = model_value (def, p, X);
%!     assert (__same_bits (a, b), "%s: model_value differs from model_core", t{1});
%!     assert (__same_bits (__octave_engine (@() model_value (def, p, X), "__model_core__"), a));
%!     m = struct ("type", t{1}, "rho_d", [0.7 0.5 0.2]);
%!     m.ks = repmat ([0; 1.3; 0.2], 1, 3);
%!     for j = 1:ns
%!       m.(def.shape{j}) = repmat (q(j,:)', 1, 3);
%!     endfor
%!     assert (__same_bits (material_x (m, X), __octave_engine (@() material_x (m, X), "__model_core__")),
%!             "%s: material_x differs without the oct-file", t{1});
%!   endfor
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!function [img, cache] = __render_and_cache (S, m, o)
%!  [img, ~, cache] = rt_render (S, m, "progress", false, o{:});
%!endfunction

%!test
%! ## rt_render's sums of the samples into the pixels (chunk_sums, which
%! ## calls the oct-file __rt_accum__ when it is built) and its shading from
%! ## the slice table (slice_rad, __rt_slice__), and its draws from an
%! ## environment map (env_sample, __env_sample__): whole renders and renders
%! ## from the trace cache, bit for bit without the oct-files, in
%! ## slice mode and lights mode, with a black and a coloured background,
%! ## chunks holding a pixel several times (chunk > pixels), and a last
%! ## chunk of one sample
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-0.8 -0.8 -0.8], "Cz", [0.7 0.7 0.7], "e", [20 20 20]);
%! sc = scene_make ("sphere", "size", [24 16]);
%! sc.spp = 4;
%! sb = sc;
%! sb.background = [0.1 0.2 0.3];
%! se = scene_make ("sphere", "size", [20 12], "light", "environment", "map", "sky");
%! se.spp = 2;
%! sf = se;
%! sf.background = [0.2 0.1 0.05];
%! cases = {sc, {"chunk", 500}; sb, {"chunk", 700}; sb, {"chunk", 1535}; sc, {"chunk", 5000};
%!          se, {"chunk", 300, "light_samples", 8}; sf, {"chunk", 900, "light_samples", 8}};
%! for i = 1:rows (cases)
%!   [S, o] = cases{i,:};
%!   [a, ~, C] = rt_render (S, m, "progress", false, o{:});
%!   b = rt_render (S, m, "progress", false, "cache", C, o{:});
%!   [a0, C0] = __octave_engine (@() __render_and_cache (S, m, o), "__rt_accum__");
%!   b0 = __octave_engine (@() rt_render (S, m, "progress", false, "cache", C0, o{:}), "__rt_accum__");
%!   assert (__same_bits (a, a0) && __same_bits (b, b0), "case %d: the sums differ without the oct-file", i);
%!   assert (__same_bits (a, b), "case %d: the cached render differs", i);
%!   assert (nnz (a) > 0);
%! endfor


%!test
%! ## sample_rays (private; the oct-file __rt_rays__ when it is built, else
%! ## pixel_samples and the one camera's __lafortune_camera_rays__): the same
%! ## rays bit for bit without the oct-file, for both cameras, stratified
%! ## cells of several shapes (spp 128: 16 x 8; 7: 7 x 1; 1), jittered and at
%! ## the cell centres, samples of every pass up to a large index
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   cd (fullfile (fileparts (which ("rt_render")), "private"));
%!   for cam = {"orthographic", "perspective"}
%!     for spp = [128 7 1]
%!       sc = scene_make ("sphere", "size", [37 53], "camera", cam{1});
%!       sc.spp = spp;
%!       ## a camera in no axis's direction: every sum's order matters
%!       sc.camera.eye = [1.3 0.7 4.9]; sc.camera.up = [0.1 1 0.05]; sc.camera.target = [0.02 -0.03 0.01];
%!       c = __lafortune_scene_camera__ (sc);
%!       k = [(0:2000)'; floor(rand (3000, 1) * 37 * 53 * spp); 37 * 53 * spp - 1; 2^40 + 17];
%!       for jit = [true false]
%!         rand ("state", 5);
%!         [O1, D1] = sample_rays (sc, c, k, jit);
%!         rand ("state", 5);
%!         [O0, D0] = __octave_engine (@() sample_rays (sc, c, k, jit), "__rt_rays__");
%!         assert (size (O1), [numel(k) 3]);
%!         assert (isequal (O1, O0) && isequal (D1, D0), "%s camera, spp %d, jitter %d: the rays differ", cam{1}, spp, jit);
%!       endfor
%!     endfor
%!   endfor
%!   ## and a whole render with the perspective camera (direct mode)
%!   sp = scene_make ("sphere", "size", [16 12], "camera", "perspective");
%!   sp.spp = 3;
%!   sp.camera.eye = [1.3 0.7 4.9]; sp.camera.up = [0.1 1 0.05];
%!   m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-0.8 -0.8 -0.8], "Cz", [0.7 0.7 0.7], "e", [20 20 20]);
%!   a = rt_render (sp, m, "progress", false);
%!   a0 = __octave_engine (@() rt_render (sp, m, "progress", false), "__rt_rays__");
%!   assert (__same_bits (a, a0) && nnz (a) > 0);
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!test
%! ## __lafortune_merl_grid__ (the oct-file __merl_grid__ when it is built):
%! ## the directions of every MERL bin, and of bins in another order, bit for
%! ## bit without the oct-file
%! [wi, wo] = __lafortune_merl_grid__ ();
%! [wi0, wo0] = __octave_engine (@() __lafortune_merl_grid__ (), "__merl_grid__");
%! assert (isequal (wi, wi0) && isequal (wo, wo0));
%! rand ("seed", 3);
%! idx = [1458000; 1; ceil(rand (5000, 1) * 1458000)];
%! [a, b] = __lafortune_merl_grid__ (idx');
%! [a0, b0] = __octave_engine (@() __lafortune_merl_grid__ (idx'), "__merl_grid__");
%! assert (isequal (a, a0) && isequal (b, b0) && isequal (a, wi(idx,:)));

%!test
%! ## __lafortune_slice_dirs__ (the oct-file __slice_dirs__ when it is
%! ## built): the same directions bit for bit without the oct-file, NaN and
%! ## signed zeros too, with a cosine per pair and one for all: random
%! ## angles, the poles (sin ti sin to <= 0), pairs no normal reaches (cos phi
%! ## clamped), angles beyond pi/2 and NaN
%! rand ("seed", 9);
%! n = 20000;
%! ti = [rand(n, 1) * 1.7; 0; 0; pi/2; 1; NaN; 0.5; -0.3; 3];
%! to = [rand(n, 1) * 1.7; 0; 0.4; 0; NaN; 1; 0.5; 0.2; 0.1];
%! cg = [2 * rand(n, 1) - 1; 1; 0.3; -1; 0.5; 0.5; NaN; 0.9; -0.99];
%! bits = @(x) typecast (x(:), "uint64");
%! for c = {cg, 0.37, -1, 1}
%!   [wi, wo] = __lafortune_slice_dirs__ (ti, to, c{1});
%!   [wi0, wo0] = __octave_engine (@() __lafortune_slice_dirs__ (ti, to, c{1}), "__slice_dirs__");
%!   assert (isequal (bits (wi), bits (wi0)) && isequal (bits (wo), bits (wo0)));
%! endfor

%!test
%! ## env_sample (private; the oct-file __env_sample__ when it is built) on
%! ## a light probe (the built-in sky without blender-data) with a rotation:
%! ## the same directions and weights bit for bit without the oct-file, for
%! ## random draws, the ends 0 and 1, values outside [0, 1] and NaN, and
%! ## draws on the CDFs' own values (texel edges)
%! here = pwd ();
%! state = rand ("state");
%! unwind_protect
%!   warning ("off", "lafortune:noLightProbe", "local");
%!   s = scene_make ("sphere", "light", "environment", "map", "courtyard", "rotation", 70);
%!   cd (fullfile (fileparts (which ("rt_render")), "private"));
%!   D = env_dist (s.light);
%!   rand ("state", 11);
%!   r = D.cdf_row(1 + floor (rand (50, 1) * D.H));
%!   u = [rand(20000, 1); 0; 1; -0.5; 2; NaN; 0.5; r];
%!   v = [rand(20000, 1); 0; 1; 2; -1; 0.3; NaN; rand(50, 1)];
%!   [L1, w1] = env_sample (D, u, v);
%!   [L0, w0] = __octave_engine (@() env_sample (D, u, v), "__env_sample__");
%!   assert (size (L1), [numel(u) 3]);
%!   assert (isequal (L1, L0) && isequal (w1, w0));
%!   assert (all (abs (sum (L1 .^ 2, 2) - 1) < 1e-12));
%! unwind_protect_cleanup
%!   cd (here);
%!   rand ("state", state);
%! end_unwind_protect

%!test
%! ## a damaged __rt_accum__ ahead on the path: one warning
%! ## lafortune:noOctFile naming rt_render, then chunk_sums's Octave
%! ## arithmetic, the same image; in a fresh octave-cli
%! m = struct ("rho_d", [0.3 0.2 0.1], "Cxy", [-0.8 -0.8 -0.8], "Cz", [0.7 0.7 0.7], "e", [20 20 20]);
%! sc = scene_make ("sphere", "size", [6 4]);
%! a = rt_render (sc, m, "progress", false);
%! [st, out] = __with_damaged ("__rt_accum__", {
%!   "m = struct ('rho_d', [0.3 0.2 0.1], 'Cxy', [-0.8 -0.8 -0.8], 'Cz', [0.7 0.7 0.7], 'e', [20 20 20]);",
%!   sprintf("a = %s;", mat2str (a(:)', 17)),
%!   "sc = scene_make ('sphere', 'size', [6 4]);",
%!   "g1 = rt_render (sc, m, 'progress', false); g2 = rt_render (sc, m, 'progress', false);",
%!   "[~, id] = lastwarn (); printf ('same %d %d, %s\\n', isequal (g1(:)', a), isequal (g2(:)', a), id);"});
%! assert (st == 0, "%s", out);
%! assert (! isempty (strfind (out, "same 1 1, lafortune:noOctFile")), out);
%! assert (numel (strfind (out, "rt_render: the oct-file __rt_accum__ does not work")) == 1, "%s", out);

%!test
%! ## damaged __merl_nearest__ and __rt_traverse__ ahead on the path: one
%! ## warning lafortune:noOctFile each, naming merl_eval and rt_intersect,
%! ## then their Octave code (merl_eval's "reference" arithmetic, the
%! ## "octave" traversal), the same values; in a fresh octave-cli
%! cases = {"__merl_nearest__", "merl_eval", "same 1 1 1", {
%!   "m = struct ('rho_d', [0.3 0.2 0.1], 'Cxy', [-0.8 -0.8 -0.8], 'Cz', [0.7 0.7 0.7], 'e', [20 20 20]);",
%!   "b = merl_synth (m); wi = [0.3 0.1 0.9; 0 0 1; 0.5 -0.2 0.8]; wi ./= sqrt (sum (wi .^ 2, 2));",
%!   "wo = [-0.2 0.3 0.9; 0.6 0 0.8; 0 0 1]; wo ./= sqrt (sum (wo .^ 2, 2));",
%!   "v1 = merl_eval (b, wi, wo); v2 = merl_eval (b, wi, wo); r = merl_eval (b, wi, wo, 'reference');",
%!   "ok = [isequal(v1, r), isequal(v2, r), any(r(:) > 0)];"};
%!          "__rt_traverse__", "rt_intersect", "same 1 1 1", {
%!   "[V, F] = mesh_torus ([12 8]); ob = struct ('type', 'mesh', 'vertices', V, 'faces', F, 'bvh', rt_bvh (V, F));",
%!   "O = [0 0 3; 0.5 0.1 3; 2 2 2]; D = [0 0 -1; 0 0 -1; -1 -1 -1]; D ./= sqrt (sum (D .^ 2, 2));",
%!   "h1 = rt_intersect (ob, O, D); h2 = rt_intersect (ob, O, D); h0 = rt_intersect (ob, O, D, 0, Inf, false, 'octave');",
%!   "ok = [isequal(h1, h0), isequal(h2, h0), any(isfinite (h0.t))];"}};
%! for i = 1:rows (cases)
%!   [oct, who, want, lines] = cases{i,:};
%!   [st, out] = __with_damaged (oct, [lines(:); {"[~, id] = lastwarn (); printf ('same %d %d %d, %s\\n', ok, id);"}]);
%!   assert (st == 0, "%s", out);
%!   assert (! isempty (strfind (out, [want ", lafortune:noOctFile"])), out);
%!   assert (numel (strfind (out, sprintf ("%s: the oct-file %s does not work", who, oct))) == 1, "%s", out);
%! endfor
