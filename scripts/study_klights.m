## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} study_klights (@var{merl_dir}, @var{quick}, @var{maps})
## How close K directional lights come to an environment map, per material
## and K (`make klights`).  POV-Ray has no glossy environment light, so
## pov_write_scene cuts the map into K lights (scene_lights); rt_render on
## the same K lights agrees with POV-Ray (test_env), so the K-light error is
## measured here with rt_render alone, and on the measured data, which is
## what a fit is compared with.  Per material (the two stand-ins and, when
## @var{merl_dir} or LAFORTUNE_KLIGHTS_MERL holds them, a set of measured
## materials from mirror-like to diffuse) and light probe: the map rendered
## with multiple importance sampling until converged (the reference) and
## once more with the next seed (the noise floor: FLIP between the two),
## then the map as K lights for each K; FLIP and relative MSE of each
## against the reference.  One ray per pixel centre in every render, so
## the renders differ only in the light.  Prints a Markdown table and
## returns it as a struct array (material, map, floor, K, flip, relmse,
## time; @var{maps}, a cell of probe names, replaces the default
## courtyard and forest); a material whose K-light FLIP at the largest K is still above
## @code{mirror_flip} is marked as one whose reflection of the map K lights
## cannot show.  It ends with the K it chooses: the smallest whose median
## K-light FLIP over the materials K lights show is within the judge step's
## noise floor at its default settings (@code{judge_floor}, from
## study_floor).
## @end deftypefn
function T = study_klights (merl_dir = getenv ("LAFORTUNE_KLIGHTS_MERL"), quick = false, maps = {})
  P = klights_settings (quick);
  if (! isempty (maps))
    P.maps = cellstr (maps);
  endif
  mats = klights_materials (merl_dir);
  printf ("study_klights: sphere %d x %d, reference %d MIS light samples a pixel, maps %s, K = %s\n\n",
          P.size(1), P.size(2), P.ref_samples, strjoin (P.maps, ", "), mat2str (P.Ks));
  T = struct ("material", {}, "map", {}, "floor", {}, "K", {}, "flip", {}, "relmse", {}, "time", {});
  for i = 1:numel (mats)
    for j = 1:numel (P.maps)
      T = [T, klights_one(mats{i}, P.maps{j}, P)];
      fflush (stdout);
    endfor
  endfor
  klights_print (T, P);
endfunction

function P = klights_settings (quick)
  P = struct ("size", [256 128], "ref_samples", 4096, "maps", {{"courtyard", "forest"}},
              "Ks", [16 32 64 128 256 512 1024], "mirror_flip", 0.3, "judge_floor", 0.1);
  if (quick)
    P.size = [64 32];
    P.ref_samples = 256;
    P.maps = {"courtyard"};
    P.Ks = [16 64];
  endif
endfunction

## The stand-ins (or the proxies), then the measured materials found.
function mats = klights_materials (merl_dir)
  mats = {};
  for name = {"green-metallic-paint", "red-plastic"}
    [~, mats{end+1}] = bench_data (name{1}, @() merl_standin (name{1}), "the built-in stand-in");
  endfor
  for name = {"steel", "aluminium", "two-layer-gold", "red-metallic-paint", ...
              "specular-white-phenolic", "beige-fabric", "pink-fabric"}
    f = fullfile (merl_dir, [name{1} ".binary"]);
    if (! isempty (merl_dir) && exist (f, "file"))
      mats{end+1} = merl_read (f);
    endif
  endfor
endfunction

## One material under one map: the reference, its floor, the K-light rows.
function T = klights_one (b, map, P)
  s = scene_make ("sphere", "size", P.size, "spp", 1, "jitter", false, "light", "environment",
                  "map", map, "light_samples", P.ref_samples, "seed", 1);
  t0 = tic ();
  ref = rt_render (s, b, "progress", false);
  s.seed = 2;
  again = rt_render (s, b, "progress", false);
  tref = toc (t0) / 2;
  floor = img_compare (ref, again).flip;
  T = struct ("material", b.name, "map", map, "floor", floor, "K", 0, "flip", NaN,
              "relmse", relmse (ref, again), "time", tref);
  for K = P.Ks
    t0 = tic ();
    img = rt_render (scene_lights (s, K), b, "progress", false);
    T(end+1) = struct ("material", b.name, "map", map, "floor", floor, "K", K,
                       "flip", img_compare (ref, img).flip, "relmse", relmse (ref, img),
                       "time", toc (t0));
  endfor
  printf ("  %s, %s: floor %.3f, FLIP %s\n", b.name, map, floor, mat2str ([T(2:end).flip], 3));
endfunction

## The default K: the smallest K whose K-light FLIP, in the median over the
## materials whose reflection K lights show, is within the judge step's
## noise floor at its default settings (P.judge_floor, study_floor's median):
## past it the lights' bias is below the noise the verdicts are made with.
function klights_choice (T, P, key)
  shown = {};
  for k = unique (key, "stable")
    r = T(strcmp (key, k{1}) & [T.K] == P.Ks(end));
    if (r.flip <= P.mirror_flip)
      shown{end+1} = k{1};
    endif
  endfor
  med = arrayfun (@(K) median ([T(ismember (key, shown) & [T.K] == K).flip]), P.Ks);
  printf ("\nMedian K-light FLIP of the %d material-map pairs K lights show: %s\n", numel (shown),
          strjoin (arrayfun (@(K, m) sprintf ("K = %d: %.3f", K, m), P.Ks, med, "uniformoutput", false), ", "));
  K = P.Ks(find (med <= P.judge_floor, 1));
  if (isempty (K))
    printf ("No K reaches the judge step's floor of %.3f in the median\n", P.judge_floor);
  else
    printf ("Chosen K: %d (the smallest median within the judge step's floor of %.3f)\n", K, P.judge_floor);
  endif
endfunction

## Relative MSE over the object's pixels: sum of squared differences over
## the sum of the reference's squares.
function r = relmse (ref, img)
  d = img - ref;
  r = sum (d(:) .^ 2) / max (sum (ref(:) .^ 2), realmin);
endfunction

function klights_print (T, P)
  printf ("\n| material | map | floor | %s | reflection |\n|---|---|---|%s---|\n",
          strjoin (arrayfun (@(K) sprintf ("K = %d", K), P.Ks, "uniformoutput", false), " | "),
          repmat ("---|", 1, numel (P.Ks)));
  key = strcat ({T.material}, "/", {T.map});
  for k = unique (key, "stable")
    r = T(strcmp (key, k{1}) & [T.K] > 0);
    cells = arrayfun (@(x) sprintf ("%.3f", x.flip), r, "uniformoutput", false);
    shown = "shown";
    if (r(end).flip > P.mirror_flip)
      shown = "**not shown by K lights**";
    endif
    printf ("| %s | %s | %.3f | %s | %s |\n", r(1).material, r(1).map, r(1).floor,
            strjoin (cells, " | "), shown);
  endfor
  printf ("\nRelative MSE against the reference:\n\n| material | map | floor | %s |\n|---|---|---|%s\n",
          strjoin (arrayfun (@(K) sprintf ("K = %d", K), P.Ks, "uniformoutput", false), " | "),
          repmat ("---|", 1, numel (P.Ks)));
  for k = unique (key, "stable")
    r = T(strcmp (key, k{1}));
    cells = arrayfun (@(x) sprintf ("%.3g", x.relmse), r(2:end), "uniformoutput", false);
    printf ("| %s | %s | %.3g | %s |\n", r(1).material, r(1).map, r(1).relmse, strjoin (cells, " | "));
  endfor
  klights_choice (T, P, key);
  t = [T([T.K] == P.Ks(end)).time];
  printf ("\nTime a render: reference %.1f s (median), K = %d %.1f s\n",
          median ([T([T.K] == 0).time]), P.Ks(end), median (t));
endfunction
