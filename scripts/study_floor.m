## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{T} =} study_floor (@var{merl_dir}, @var{quick})
## The noise floor of the judge step's reference under each light probe of
## JUDGE, per material and sampling density (`make floor`): the measured
## data on the judge's sphere (SIZE, JUDGE_SPP, JUDGE_SAMPLES of
## config.mk), rendered twice with seeds 1 and 2, the floor the FLIP
## between the two, for the two densities of brdf_density: "table" (the
## data's own table, rt_render's default) and "fit" (2 Lafortune lobes
## made for sampling).  Materials: the two stand-ins and every *.binary of
## @var{merl_dir} (or LAFORTUNE_FLOOR_MERL).  Prints a Markdown table (the
## floor, the seconds a render and the seconds to make the density) and
## returns it as a struct array; the issue's target is a floor of at most
## 0.05 on every material.
## @end deftypefn
function T = study_floor (merl_dir = getenv ("LAFORTUNE_FLOOR_MERL"), quick = false)
  if (quick)
    setenv ("QUICK", "1");                # config.mk's _QUICK values
  endif
  c = repro_config ();
  maps = {c.judge(strcmp ({c.judge.type}, "environment")).map};
  files = floor_files (merl_dir);
  printf ("study_floor: sphere %d x %d, %d spp x %d light samples, MIS; maps %s\n\n", c.size(1),
          c.size(2), c.judge_spp, c.judge_samples, strjoin (maps, ", "));
  T = struct ("material", {}, "map", {}, "density", {}, "floor", {}, "time", {}, "time_density", {});
  for i = 1:numel (files)
    b = floor_read (files{i});
    for d = {"table", "fit"}
      t0 = tic ();
      [~, b.sampler] = brdf_density (rmfield (b, intersect (fieldnames (b), {"sampler"})), d{1});
      td = toc (t0);
      for m = maps
        s = scene_make ("sphere", "size", c.size, "spp", c.judge_spp, "light", "environment",
                        "map", m{1}, "light_samples", c.judge_samples, "seed", 1);
        t0 = tic ();
        a = rt_render (s, b, "progress", false);
        s.seed = 2;
        a2 = rt_render (s, b, "progress", false);
        T(end+1) = struct ("material", b.name, "map", m{1}, "density", d{1},
                           "floor", img_compare (a, a2).flip, "time", toc (t0) / 2, "time_density", td);
        printf ("  %s, %s, %s: floor %.3f (%.1f s a render)\n", b.name, m{1}, d{1}, T(end).floor, T(end).time);
        fflush (stdout);
      endfor
    endfor
  endfor
  floor_print (T, maps);
endfunction

## The stand-ins (the proxies, else the built-in ones: bench_data), then
## every *.binary of MERL_DIR, each read when its turn comes
function files = floor_files (merl_dir)
  files = {"green-metallic-paint", "red-plastic"};
  if (! isempty (merl_dir))
    l = dir (fullfile (merl_dir, "*.binary"));
    files = [files, cellfun(@(n) fullfile (merl_dir, n), {l.name}, "uniformoutput", false)];
  endif
endfunction

function b = floor_read (f)
  if (exist (f, "file"))
    b = merl_read (f);
  else
    [~, b] = bench_data (f, @() merl_standin (f), "the built-in stand-in");
  endif
endfunction

function floor_print (T, maps)
  printf ("\n| material |");
  printf (" %s, table | %s, fit |", [maps; maps]{:});
  printf (" s a render (table) | density s (table, fit) |\n|---|%s---|---|\n",
          repmat ("---|", 1, 2 * numel (maps)));
  for name = unique ({T.material}, "stable")
    r = T(strcmp ({T.material}, name{1}));
    printf ("| %s |", name{1});
    for m = maps
      for d = {"table", "fit"}
        printf (" %.3f |", r(strcmp ({r.map}, m{1}) & strcmp ({r.density}, d{1})).floor);
      endfor
    endfor
    t = r(strcmp ({r.density}, "table"));
    f = r(strcmp ({r.density}, "fit"));
    printf (" %.1f | %.2f, %.2f |\n", median ([t.time]), t(1).time_density, f(1).time_density);
  endfor
  t = T(strcmp ({T.density}, "table"));
  f = T(strcmp ({T.density}, "fit"));
  printf ("\nfloor at most 0.05: table %d of %d, fit %d of %d; worst: table %.3f, fit %.3f\n",
          sum ([t.floor] <= 0.05), numel (t), sum ([f.floor] <= 0.05), numel (f), max ([t.floor]),
          max ([f.floor]));
endfunction
