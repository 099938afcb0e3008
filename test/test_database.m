## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## Integration test of `make database` at tiny settings (24 x 12 pixels,
## 2 samples per pixel, 1 and 2 lobes) on a scratch folder of three files:
## the two MERL-format files of ../shared/data/merl-proxy (or, when absent,
## the built-in stand-ins written in MERL format) and a truncated file.
##   - the run is killed twice and restarted: it finishes, every material has
##     its rows, the truncated file one row naming the error;
##   - FLIP, Delta E (CIEDE2000) and hue beside PSNR for both renderers
##     (table.csv, report.md, summary.json), the pairs of fits PSNR and FLIP
##     rank differently, the verdict by FLIP, figures/flip-lobes.png;
##   - a rerun does no work and rewrites nothing;
##   - a change to inst/pov_render.m (make -W) re-runs only the fits' renders
##     and what follows, not the fits nor the measured-data renders;
##   - the models compared (MODELS="lafortune ggx", in-plane and general
##     methods, METALS=red-plastic): rows per model, the report's section
##     "Models compared" (best model per material, medians of metals and
##     non-metals, sizes, energy, where Lafortune loses), and the Lafortune
##     rows equal to those of the MODELS=lafortune run;
##   - GNU parallel over ssh (HOSTS=, a real OpenSSH server started by
##     test/cluster.sh on 127.0.0.1 with throwaway keys, two host names) gives
##     the same table as the local run; a remote Octave killed with kill -9
##     halfway through a material: the run completes that material, and a
##     rerun with --resume-failed does no work;
##   - Slurm (scripts/db_slurm_submit on a real single-node cluster, munged,
##     slurmctld and slurmd started by test/cluster.sh): the job array and the
##     merge job give the same table; an array task cancelled halfway
##     (scancel): the merge job completes its material and nothing partial
##     is left.
## The ssh and Slurm parts skip with a message when their Debian packages
## (openssh-server and openssh-client; slurm-wlm and munge) are absent; a
## daemon that is installed but does not start fails the test with its
## message.
## Run by `make check` (which sets LAFORTUNE_TOP).

%!function top = __top ()
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! assert (exist (fullfile (top, "Makefile"), "file") == 2, "run from the project's top folder");
%!endfunction

%!function s = __opts ()
%! ## the tiny settings of every run of this test
%! s = "QUICK=1 SIZE='24 12' SPP=2 HEMI_SAMPLES=2000 LOBES='1 2' POV_AA=0";
%!endfunction

%!function [st, txt] = __make (top, db, merl, extra, only = false)
%! ## make (extra: goals and variables) at the test's settings; with ONLY, the command line
%! cmd = sprintf ("make --no-print-directory -C '%s' %s DB='%s' MERL_DIR='%s' %s 2>&1",
%!                top, extra, db, merl, __opts ());
%! if (only)
%!   [st, txt] = deal (0, cmd);
%! else
%!   [st, txt] = system (cmd);
%! endif
%!endfunction

%!function T = __table (file)
%! ## the rows of table.csv without the time columns, for comparing runs
%! L = strsplit (strtrim (fileread (file)), "\n");
%! head = strsplit (L{1}, ",");
%! keep = cellfun ("isempty", regexp (head, "time", "once"));
%! T = {};
%! for i = 1:numel (L)
%!   f = regexp (L{i}, ',(?=(?:[^"]*"[^"]*")*[^"]*$)', "split");
%!   T(end+1,:) = f(keep);
%! endfor
%!endfunction

%!function __data (merl)
%! mkdir (merl);
%! proxy = getenv ("MERL_PROXY_DIR");
%! for m = {"green-metallic-paint", "red-plastic"}
%!   src = fullfile (proxy, [m{1} ".binary"]);
%!   if (! isempty (proxy) && exist (src, "file"))
%!     [err, msg] = symlink (src, fullfile (merl, [m{1} ".binary"]));
%!     assert (err == 0, "%s", msg);
%!   else
%!     merl_write (fullfile (merl, [m{1} ".binary"]), merl_standin (m{1}));
%!   endif
%! endfor
%! ## names that no rule, command or scene file may see: left out with a warning
%! for n = __bad_names ()
%!   [err, msg] = symlink (fullfile (merl, "red-plastic.binary"), fullfile (merl, [n{1} ".binary"]));
%!   assert (err == 0, "%s", msg);
%! endfor
%! fid = fopen (fullfile (merl, "truncated.binary"), "w");
%! fwrite (fid, [90 180 360], "int32");
%! fwrite (fid, ones (1000, 1), "double");
%! fclose (fid);
%!endfunction

%!function n = __bad_names ()
%! n = {"has space", "it's", "a$b", "back`tick", "semi;colon", "caf\303\251", "-dash"};
%!endfunction
%!function __check_bad_names (merl, txt)
%! ## each file with a bad name named once, with the names allowed
%! for n = __bad_names ()
%!   w = sprintf ("database: warning: skipped the file '%s': a material's name may hold only", fullfile (merl, [n{1} ".binary"]));
%!   assert (numel (strfind (txt, w)), 1, txt);
%! endfor
%!endfunction
%!function [st, txt] = __cluster (top, what, dir)
%! ## test/cluster.sh: start or stop the test's own daemons (exit 2: not installed)
%! [st, txt] = system (sprintf ("bash '%s' %s '%s' 2>&1", fullfile (top, "test", "cluster.sh"), what, dir));
%!endfunction

%!function __bg (cmd, pidf, statf)
%! ## CMD in the background, in a process group of its own (id written to
%! ## PIDF); its output goes to STATF.log and its exit status to STATF when it ends
%! full = sprintf ("setsid sh -c 'echo $$ > \"$0\"; sh -c \"$1\" > \"$2.log\" 2>&1; echo $? > \"$2\"' '%s' '%s' '%s' > /dev/null 2>&1 &",
%!                 pidf, strrep (cmd, "'", "'\\''"), statf);
%! assert (system (full), 0);
%!endfunction

%!function ok = __poll (f, secs)
%! ## wait at most SECS seconds until F () is true
%! ok = false;
%! for i = 1:ceil (secs / 0.2)
%!   if (f ())
%!     ok = true;
%!     return;
%!   endif
%!   pause (0.2);
%! endfor
%!endfunction

%!function pid = __descendant (root, pattern)
%! ## the id of an Octave process below process ROOT whose command line
%! ## matches PATTERN (0: none)
%! pid = 0;
%! [~, txt] = system ("ps -e -o pid=,ppid=,comm=,args=");
%! P = regexp (txt, '^\s*(\d+)\s+(\d+)\s+(\S+)\s+(.*)$', "tokens", "lineanchors", "dotexceptnewline");
%! ids = cellfun (@(t) str2double (t{1}), P);
%! par = cellfun (@(t) str2double (t{2}), P);
%! for i = 1:numel (P)
%!   if (isempty (regexp (P{i}{3}, "^octave", "once")) || isempty (regexp (P{i}{4}, pattern, "once")))
%!     continue;
%!   endif
%!   p = par(i);
%!   for up = 1:30
%!     if (p == root)
%!       pid = ids(i);
%!       return;
%!     endif
%!     k = find (ids == p, 1);
%!     if (isempty (k))
%!       break;
%!     endif
%!     p = par(k);
%!   endfor
%! endfor
%!endfunction

%!function left = __partial (db)
%! ## files a killed step could leave behind: temporaries of atomic writes
%! [~, left] = system (sprintf ("find '%s' -name '*.tmp*'", db));
%! left = strtrim (left);
%!endfunction

%!function J = __joblog (file)
%! ## GNU parallel's --joblog: one row per job, {host, exit value, signal, material}
%! L = strsplit (strtrim (fileread (file)), "\n");
%! J = cell (0, 4);
%! for i = 2:numel (L)
%!   f = strsplit (L{i}, "\t");
%!   J(end+1,:) = {f{2}, str2double(f{7}), str2double(f{8}), regexp(f{9}, "db-(\\S+)", "tokens", "once"){1}};
%! endfor
%!endfunction

%!function txt = __slurm_wait (ids, secs)
%! ## wait at most SECS seconds until Slurm jobs IDS (cell of strings) have left the queue
%! q = sprintf ("squeue -h -j %s -o '%%i %%t' 2>&1", strjoin (ids, ","));
%! done = @() isempty (strtrim (nthargout (2, @system, q)));
%! assert (__poll (done, secs), sprintf ("Slurm jobs %s still queued after %d s: %s",
%!                                       strjoin (ids, ","), secs, nthargout (2, @system, q)));
%! txt = "";
%!endfunction

%!shared top, out, merl, T
%! top = __top ();
%! out = tempname ();
%! merl = fullfile (out, "merl");
%! T = {};
%! mkdir (out);
%! __data (merl);

%!test
%! db = fullfile (out, "db");
%! pidf = fullfile (out, "make.pid");
%! unwind_protect
%!   ## killed twice, at different points, then finished
%!   for t = [3 2]
%!     ## make in a process group of its own, whose id the shell writes down
%!     [~, cmd] = __make (top, db, merl, "-j2 database", true);
%!     __bg (cmd, pidf, fullfile (out, "kill.status"));
%!     pause (t);
%!     pid = str2double (fileread (pidf));
%!     assert (pid > 1);
%!     assert (system (sprintf ("kill -TERM -%d", pid)), 0);   # the run was still going
%!     pause (1);
%!     system (sprintf ("kill -KILL -%d 2>/dev/null", pid));
%!     ## nothing of it left running (zombies not yet reaped do not count)
%!     alive = sprintf ("ps -e -o pgid=,stat= | awk '$1 == %d && $2 !~ /Z/' | grep -q .", pid);
%!     for w = 1:50
%!       if (system (alive) != 0)
%!         break;
%!       endif
%!       pause (0.1);
%!     endfor
%!     assert (system (alive) != 0, "the killed run is still alive");
%!   endfor
%!   assert (! exist (fullfile (db, "table.csv"), "file"), "the killed runs should not have finished");
%!   [st, txt] = __make (top, db, merl, "-j2 database");
%!   assert (st == 0, "%s", txt);
%!   __check_bad_names (merl, txt);
%!   T = __table (fullfile (db, "table.csv"));
%!   ## the published fits (PUBLISHED) of both materials, where ../shared has them
%!   npub = 2 * (exist (fullfile (top, "..", "shared", "data", "ngan2005", "lafortune-1lobe.tsv"), "file") == 2);
%!   ## head, 2 materials x 3 methods x 2 lobe counts, the published fits, 1 error
%!   assert (rows (T), 1 + 2 * 3 * 2 + npub + 1);
%!   col = @(n) find (strcmp (T(1,:), n));
%!   assert ([col("method"), col("model"), col("lobes"), col("status"), col("error")], 2:6);
%!   assert (nnz (strcmp (T(:,2), "ngan2005") & strcmp (T(:,4), "1")), npub);
%!   ## one model, Lafortune's
%!   assert (unique (T(strcmp (T(:,5), "ok"),3)), {"lafortune"});
%!   rep = fileread (fullfile (db, "report.md"));
%!   if (npub)
%!     assert (! isempty (regexp (rep, ["The recommended 1-lobe fit \\(general\\) is better than the " ...
%!                                      "published one on \\d of 2 materials"])), rep);
%!     assert (! isempty (strfind (rep, "toolbox's to the very data they are compared with here. Judged by held-out FLIP")), rep);
%!   else
%!     printf ("skipped: the published fits of ../shared/data/ngan2005 (absent)\n");
%!   endif
%!   assert (nnz (strcmp (T(:,2), "general")), 2 * 2);   # the recommended fit is a method
%!   k = strcmp (T(:,1), "truncated");
%!   assert (nnz (k), 1);
%!   assert (T{k,5}, "error");
%!   assert (! isempty (strfind (T{k,6}, "truncated")), T{k,6});
%!   assert (all (strcmp (T(! k & ! strcmp (T(:,1), "material"),5), "ok")));
%!   rep = fileread (fullfile (db, "report.md"));
%!   assert (! isempty (strfind (rep, "**truncated**: fit: merl_read")));
%!   ## each method's materials whose render falls with one more lobe
%!   assert (numel (regexp (rep, "; more lobes render worse: ")), 3);
%!   S = jsondecode (fileread (fullfile (db, "summary.json")));
%!   assert (isfield (S.methods.general, "largest_flip_rise") && S.methods.general.largest_flip_rise >= 0);
%!   assert (isfield (S.methods.general, "largest_flip_rise_in_sample") && S.methods.general.largest_flip_rise_in_sample >= 0);
%!   ## every fit rendered by both renderers
%!   assert (all (isfinite (S.psnr_rt.scene(isfinite (S.psnr.scene)))));
%!   assert (numel (strfind (rep, " (in-sample, POV-Ray: ")) == 3, "%s", rep);
%!   ## held out: every fit judged under the lights of JUDGE; the verdicts on them
%!   assert (! isempty (strfind (S.verdict, "held-out FLIP (the mean over courtyard, forest, light from [0.2 1 -0.4]")), S.verdict);
%!   assert (size (S.heldout.flip.general), [3 2]);
%!   assert (all (isfinite (S.heldout.flip.general(1:2,:)(:))));
%!   assert (! isempty (regexp (rep, "Judged by held-out FLIP \\(the mean over courtyard, forest")), rep);
%!   ## every verdict states its noise: the measured data rendered twice under
%!   ## each light, their FLIP the floor, beside the verdicts
%!   J = jsondecode (fileread (fullfile (db, "materials", "red-plastic", "judge", "red-plastic.json")));
%!   assert (numel (J.noise_flip), 3);
%!   assert (all (isfinite (J.noise_flip) & J.noise_flip >= 0 & J.noise_flip < 1), mat2str (J.noise_flip));
%!   assert (J.noise_flip_mean, mean (J.noise_flip), 1e-12);
%!   assert (J.time_noise > 0);
%!   assert (size (S.heldout.noise_flip), [3 3]);
%!   assert (S.heldout.noise_flip_mean(2), J.noise_flip_mean, 1e-12);   # red-plastic, the second material
%!   assert (all (isfinite (S.heldout.noise_flip_mean(1:2))));
%!   assert (! isempty (regexp (rep, "Every held-out verdict states its noise: .+ median 0\\.\\d{3} over the materials")), rep);
%!   nc = find (strcmp (T(1,:), "flip_heldout_noise"));
%!   assert (numel (nc), 1);
%!   r = strcmp (T(:,1), "red-plastic");
%!   assert (str2double (T(r,nc)), repmat (J.noise_flip_mean, nnz (r), 1), 1e-5);
%!   ## the published baseline: a fit within the floor of the other ties
%!   if (npub)
%!     P = S.published;
%!     tie = abs (P.recommended_flip - P.flip) <= P.noise_flip;
%!     assert (P.recommended_better, nnz (! tie & P.recommended_flip < P.flip));
%!     assert (numel (P.tied), nnz (tie));
%!   endif
%!   ## the summary: median PSNR, FLIP, Delta E, hue per method and lobe count
%!   assert (! isempty (regexp (rep, ["\\| in-plane \\(the paper's method\\) \\| 2 \\| \\d+\\.\\d\\d \\| " ...
%!                                    "\\d\\.\\d{3} \\| \\d+\\.\\d\\d \\| \\d+\\.\\d \\|"])), rep);
%!   ## FLIP, Delta E (CIEDE2000) and hue beside PSNR in table.csv, both renderers
%!   okr = strcmp (T(:,5), "ok");
%!   for q = {"flip", "deltae", "hue"}
%!     for r = {"pov", "rt", "heldout"}
%!       col = find (strcmp (T(1,:), [q{1} "_" r{1}]));
%!       assert (numel (col) == 1, "%s_%s", q{1}, r{1});
%!       v = str2double (T(okr,col));
%!       assert (numel (v), 2 * 3 * 2 + npub);
%!       assert (all (isfinite (v) & v >= 0 & (v <= 1 | ! strcmp (q{1}, "flip"))), [q{1} "_" r{1}]);
%!     endfor
%!   endfor
%!   assert (size (S.flip.scene), [3 2]);      # materials x lobe counts, as S.psnr
%!   assert (size (S.flip_rt.scene), [3 2]);
%!   assert (numel (strfind (rep, "FLIP")) > 10);
%!   ## the pairs of fits that PSNR and FLIP rank differently
%!   assert (! isempty (regexp (rep, ["PSNR and FLIP rank \\d+ of 30 pairs of fits of the same material " ...
%!                                    "differently \\(\\d+ %; \\d+ with FLIP apart by more than [\\d.]+\\), " ...
%!                                    "and \\d+ of 6 pairs of materials fitted by the same method"])), rep);
%!   assert (S.rank_disagreement.pov.within_pairs, 2 * 15);   # 2 materials, 6 fits each: 15 pairs
%!   assert (S.rank_disagreement.pov.across_pairs, 3 * 2);    # 3 methods x 2 lobe counts, 1 pair
%!   ## the recommended fit's FLIP rises, per renderer; the verdict by FLIP
%!   assert (! isempty (regexp (rep, ["The recommended fit \\(general\\) renders worse with one more lobe " ...
%!                                    "\\(up by more than [\\d.]+, FAIL_FLIP_DROP\\) by held-out FLIP .+ on: .+\\. " ...
%!                                    "By in-sample FLIP \\(POV-Ray, the scene's own light\\): .+\\."])), rep);
%!   assert (! isempty (regexp (rep, "has FLIP above [\\d.]+ \\(FAIL_FLIP")), rep);
%!   ## the plots (3 panels) and a contact sheet (3 panels a row): not blank,
%!   ## with coloured lines or renders
%!   for f = {"figures/psnr-lobes.png", [560 1560 3]; "figures/flip-lobes.png", [560 1560 3]; ...
%!            "materials/red-plastic/sheet/red-plastic.png", [NaN 768 3]; ...
%!            "materials/red-plastic/sheet/red-plastic-heldout.png", [NaN 768 3]}'
%!     img = double (imread (fullfile (db, f{1})));
%!     sz = size (img);
%!     assert (isequal (sz(isfinite (f{2})), f{2}(isfinite (f{2}))), [f{1} ": " mat2str(sz)]);
%!     assert (std (img(:)) > 10, f{1});
%!     coloured = max (img, [], 3) - min (img, [], 3) > 60;
%!     assert (nnz (coloured) > 200, f{1});
%!   endfor
%!   for f = {"figures/psnr-lobes.png", "gallery/index.html", "summary.json", ...
%!            "materials/red-plastic/sheet/red-plastic.png", ...
%!            "materials/red-plastic/fit/red-plastic-general-2.json", ...
%!            "materials/green-metallic-paint/render/green-metallic-paint-inplane-1.exr"}
%!     assert (exist (fullfile (db, f{1}), "file") == 2, f{1});
%!   endfor
%!   ## every step record has the same head and reads with jsondecode
%!   F = jsondecode (fileread (fullfile (db, "materials", "red-plastic", "fit", "red-plastic.json")));
%!   assert ({F.material, F.step, F.status}, {"red-plastic", "fit", "ok"});
%!   ## the traces in brdf_fit's shape (K x 2 per channel), as jsondecode reads them
%!   tr = F.inplane.trace;
%!   assert ((iscell (tr) && numel (tr) == 3 && all (cellfun (@columns, tr) == 2))
%!           || (size (tr, 1) == 3 && size (tr, 3) == 2));
%!   ## the models' parameters in the record, as in their files (the report reads them here)
%!   md = brdf_import (fullfile (db, "materials", "red-plastic", "fit", "red-plastic-inplane-2.json"));
%!   pr = F.inplane.parameters(2);
%!   for f = {"rho_d", "Cxy", "Cz", "e"}
%!     assert (reshape (pr.(f{1}), [], 3), md.(f{1}), 1e-14 * max (abs (md.(f{1})(:))));
%!   endfor
%!   assert (all (diff (mean (F.inplane.errors.inplane.rmse, 2)) <= 1e-12));
%!   ## a rerun does no work
%!   t0 = dir (fullfile (db, "table.csv")).datenum;
%!   [st, txt] = __make (top, db, merl, "-j2 database");
%!   assert (st == 0, "%s", txt);
%!   assert (isempty (regexp (txt, "fitting|rendering|POV-Ray|held-out light|FAILED|database: \\d+ materials")), txt);
%!   assert (dir (fullfile (db, "table.csv")).datenum, t0);
%!   ## a change to brdf_import (which only the fits' renders call) re-runs
%!   ## the fits' renders, not the fits nor the measured renders (make passes -W
%!   ## to no sub-make: ask for the table itself)
%!   [st, txt] = __make (top, db, merl, sprintf ("-W inst/brdf_import.m -j2 '%s'", fullfile (db, "table.csv")));
%!   assert (st == 0, "%s", txt);
%!   assert (! isempty (regexp (txt, "\\[red-plastic\\] POV-Ray render")), txt);
%!   assert (isempty (regexp (txt, "fitting|rendering the measured")), txt);
%!   assert (isequal (__table (fullfile (db, "table.csv")), T));
%!   ## the models section with one model
%!   assert (! isempty (strfind (rep, "Only the Lafortune model was fitted (MODELS = lafortune)")), rep);
%!   assert (! isempty (regexp (rep, "\\| lafortune \\| 2 \\| 21 \\| 168 \\| \\d+ \\| 0\\.\\d{3} \\| - \\| 0\\.\\d{3} \\|")), rep);

%! unwind_protect_cleanup
%!   if (exist (pidf, "file"))     # a run this test started and could not stop
%!     system (sprintf ("kill -KILL -%d 2>/dev/null", str2double (fileread (pidf))));
%!     unlink (pidf);
%!   endif
%! end_unwind_protect


%!test
%! ## the models compared: MODELS="lafortune ggx" with the in-plane and
%! ## general methods (a GGX fit of a scene table takes 30 s or more),
%! ## red-plastic counted as a metal (METALS) for the split
%! assert (! isempty (T), "the local run above failed");
%! addpath (fullfile (top, "scripts"));
%! unwind_protect
%!   ## the method names: TABLE[_COLOR][_MODEL], METHODS crossed with MODELS
%!   p = repro_method ("inplane_shared_ggx");
%!   assert ({p.table, p.color, p.model, p.base, p.opts}, {"inplane", "shared", "ggx", "inplane_shared", {"color", "shared"}});
%!   p = repro_method ("scene");
%!   assert ({p.table, p.color, p.model, p.base}, {"scene", "", "lafortune", "scene"});
%!   ## one label per method, for both reports and the figures
%!   assert (p.label, "scene (for the scene's light)");
%!   assert (repro_method ("general").label, "general (recommended)");
%!   assert (repro_method ("inplane_shared_ggx").label, "in-plane, shared colour, ggx");
%!   assert (repro_method ("hemisphere_ward").label, "hemisphere, ward");
%!   assert (repro_method ({"inplane", "scene_shared", "hemisphere_ward"}, {"lafortune", "ggx"}),
%!           {"inplane", "scene_shared", "hemisphere_ward", "inplane_ggx", "scene_shared_ggx"});
%!   ## JUDGE: light probes and directions X,Y,Z; a setting set empty on make's
%!   ## command line (LAFORTUNE_EMPTY) is empty, not config.mk's default
%!   env0 = {getenv("JUDGE"), getenv("LAFORTUNE_EMPTY")};
%!   unwind_protect
%!     setenv ("JUDGE", "studio 0,2,0");
%!     c = repro_config ();
%!     assert ({c.judge.type}, {"environment", "directional"});
%!     assert ({c.judge.map}, {"studio", ""});
%!     assert (c.judge(2).direction, [0 1 0]);
%!     for bad = {"0,0,0", "1,2", "Studio!"}
%!       setenv ("JUDGE", bad{1});
%!       try
%!         repro_config ();
%!         error ("JUDGE=%s was taken", bad{1});
%!       catch err
%!         assert (err.identifier, "lafortune:badConfig");
%!         assert (! isempty (strfind (err.message, ["JUDGE has '" bad{1} "'"])), err.message);
%!       end_try_catch
%!     endfor
%!     unsetenv ("JUDGE");
%!     assert (numel (repro_config ().judge), 3);       # config.mk's default
%!     setenv ("LAFORTUNE_EMPTY", "PUBLISHED JUDGE");
%!     c = repro_config ();
%!     assert (isempty (c.judge) && isempty (c.published));
%!   unwind_protect_cleanup
%!     setenv ("JUDGE", env0{1});
%!     setenv ("LAFORTUNE_EMPTY", env0{2});
%!   end_unwind_protect
%!   ## a folder that another step made meanwhile is no error (make -j: two
%!   ## materials' first steps make results/data at once)
%!   d = fullfile (out, "mk", "a", "b");
%!   repro_mkdir (d);
%!   repro_mkdir (d);
%!   assert (isfolder (d));
%!   try
%!     repro_mkdir ("/proc/no/such/folder");
%!     error ("made a folder under /proc");
%!   catch err
%!     assert (err.identifier, "lafortune:unwritable");
%!   end_try_catch
%!   fail ('repro_method ("scene_lafortune")', "unknown method");
%!   fail ('repro_method ("scene_shared_ggx_ward")', "unknown method");
%! unwind_protect_cleanup
%!   rmpath (fullfile (top, "scripts"));
%! end_unwind_protect
%! db = fullfile (out, "db-models");
%! ## without held-out lights (JUDGE= on make's command line): every verdict in-sample, and said so
%! [st, txt] = __make (top, db, merl, "-j2 database MODELS='lafortune ggx' METHODS='inplane general' METALS=red-plastic JUDGE=");
%! assert (st == 0, "%s", txt);
%! U = __table (fullfile (db, "table.csv"));
%! col = @(n) find (strcmp (U(1,:), n));
%! okr = strcmp (U(:,col("status")), "ok");
%! npub = nnz (strcmp (T(:,2), "ngan2005"));
%! ## 2 materials x 2 methods x 2 models x 2 lobe counts, the published fits, the truncated file
%! assert (rows (U), 1 + 2 * 2 * 2 * 2 + npub + 1);
%! for m = {"inplane_ggx", "general_ggx"}
%!   r = strcmp (U(:,2), m{1});
%!   assert (nnz (r), 2 * 2, m{1});
%!   assert (all (strcmp (U(r,col("model")), "ggx")));
%!   ## the numbers a model holds, from its type's fields; its albedo
%!   k = str2double (U(r,col("lobes")));
%!   nf = numel (brdf_model ("ggx").fields);
%!   assert (str2double (U(r,col("params"))), 3 + 3 * (nf - 1) * k);
%!   assert (all (str2double (U(r,col("json_bytes"))) > 100));
%!   a = str2double (U(r,col("albedo_max")));
%!   assert (all (isfinite (a) & a > 0), mat2str (a));
%!   v = str2double (U(r,col("flip_pov")));
%!   assert (all (v > 0 & v < 1), mat2str (v));
%!   assert (all (isfinite (str2double (U(r,col("alpha1_g"))))));
%!   assert (all (cellfun ("isempty", U(r,col("cxy1_g")))));
%! endfor
%! ## the Lafortune rows (and the error row) are those of the MODELS=lafortune run, column by
%! ## column, but for the held-out ones: none without JUDGE
%! [in, cu] = ismember (T(1,:), U(1,:));
%! assert (nnz (! in), 3 + 3);                # rmse, log_rmse, cos_rmse on the scene table; a FLIP per light
%! h = ! cellfun ("isempty", regexp (T(1,:), "heldout"));
%! assert (all (cellfun ("isempty", U(2:end,cu(in & h)))(:)));
%! in &= ! h;
%! lt = ismember (T(:,2), {"method", "inplane", "general", "ngan2005"}) | strcmp (T(:,1), "truncated");
%! lu = ismember (U(:,2), {"method", "inplane", "general", "ngan2005"}) | strcmp (U(:,1), "truncated");
%! assert (isequal (U(lu,cu(in)), T(lt,in)));
%! ## the report's section
%! rep = fileread (fullfile (db, "report.md"));
%! assert (! isempty (strfind (rep, "## Models compared")), rep);
%! assert (! isempty (strfind (rep, "Judged by in-sample FLIP (POV-Ray renders in the light the scene fits were made for: JUDGE is empty)")), rep);
%! assert (! exist (fullfile (db, "materials", "red-plastic", "sheet", "red-plastic-heldout.png"), "file"));
%! J = jsondecode (fileread (fullfile (db, "materials", "red-plastic", "judge", "red-plastic.json")));
%! assert (isempty (J.lights));
%! assert (isempty (J.noise_flip) && (isempty (J.noise_flip_mean) || isnan (J.noise_flip_mean)));
%! assert (isempty (strfind (rep, "states its noise")), rep);
%! x = J.general_ggx(1).flip_mean;
%! assert (isempty (x) || isnan (x));
%! assert (! isempty (strfind (rep, "Metals (METALS in config.mk): red-plastic; the other 1 processed materials are the non-metals.")), rep);
%! for m = {"green-metallic-paint \\| no", "red-plastic \\| yes"}
%!   assert (! isempty (regexp (rep, ["\\| " m{1} " \\| \\*\\*(lafortune|ggx)\\*\\* 0\\.\\d{3} \\((inplane|general)(_ggx)?\\) \\| " ...
%!                                    "\\*\\*(lafortune|ggx)\\*\\* 0\\.\\d{3} "])), m{1});
%! endfor
%! ## medians per model and lobe count: sizes, all, metals, non-metals, dE, best on, albedo > 1
%! assert (! isempty (regexp (rep, ["\\| ggx \\| 2 \\| 21 \\| 168 \\| \\d+ \\| 0\\.\\d{3} \\| 0\\.\\d{3} \\| 0\\.\\d{3} \\| " ...
%!                                  "\\d+\\.\\d\\d \\| \\d of 2 \\| \\d of 4 \\|"])), rep);
%! assert (! isempty (regexp (rep, "\\| lafortune \\| 1 \\| 12 \\| 96 \\| \\d+ \\| 0\\.\\d{3} \\| 0\\.\\d{3} \\| 0\\.\\d{3} \\| [\\d.]+ \\| \\d of 2 \\| - \\|")), rep);
%! assert (! isempty (regexp (rep, ["It loses on \\d / \\d of the 2 processed materials \\(1 / 2 lobes\\); " ...
%!                                  "on the metals on \\d / \\d of 1, on the non-metals on \\d / \\d of 1\\."])), rep);
%! S = jsondecode (fileread (fullfile (db, "summary.json")));
%! assert (S.models.models, {"lafortune"; "ggx"});
%! assert (S.models.per_model.ggx.params(:)', [12 21]);
%! assert (S.models.per_model.lafortune.best_on + S.models.per_model.ggx.best_on, [2; 2]);
%! assert (numel (S.models.best), 2);
%! ## where Lafortune loses, when it does: each row's FLIP gain is the difference of the two
%! for x = S.models.lafortune_loses(:)'
%!   assert (x.flip_gain, x.flip - x.winner_flip, 1e-12);
%!   assert (x.flip_gain > 0);
%! endfor
%! assert (! isempty (regexp (rep, "\\| (red-plastic|green-metallic-paint) \\| [12] \\| 0\\.\\d{3} \\((inplane|general)\\) \\| ggx, 0\\.\\d{3} \\(")) || isempty (S.models.lafortune_loses));
%! ## the sheets have a row per method
%! assert (exist (fullfile (db, "materials", "red-plastic", "sheet", "red-plastic.png"), "file") == 2);

%!test
%! ## GNU parallel over ssh: a real OpenSSH server on 127.0.0.1, hosts node-a and node-b
%! assert (! isempty (T), "the local run above failed");
%! if (system ("command -v parallel >/dev/null 2>&1") != 0)
%!   error ("the GNU parallel path needs 'parallel' (Debian package parallel, a dependency)");
%! endif
%! sshd = fullfile (out, "sshd");
%! pidf = fullfile (out, "ssh-run.pid");
%! [st, txt] = __cluster (top, "sshd-start", sshd);
%! if (st == 2)
%!   printf ("skipped: the GNU parallel path over ssh: %s", txt);
%!   return;
%! endif
%! unwind_protect
%!   assert (st == 0, "%s", txt);
%!   hosts = fullfile (out, "hosts");
%!   fid = fopen (hosts, "w"); fputs (fid, "1/node-a\n1/node-b\n"); fclose (fid);
%!   via = @(jl) sprintf ("database HOSTS='%s' PARALLEL_OPTS=\"--ssh 'ssh -F %s' --joblog '%s'\"",
%!                        hosts, fullfile (sshd, "ssh_config"), jl);
%!   db = fullfile (out, "db-ssh");
%!   jl = fullfile (out, "ssh.joblog");
%!   [st, txt] = __make (top, db, merl, via (jl));
%!   assert (st == 0, "%s", txt);
%!   ## every material ran on an ssh host and finished there
%!   J = __joblog (jl);
%!   assert (sort (J(:,4)), {"green-metallic-paint"; "red-plastic"; "truncated"});
%!   assert (all (ismember (J(:,1), {"node-a", "node-b"})), strjoin (J(:,1), " "));
%!   assert (all ([J{:,2}] == 0), "%s", txt);
%!   nlog = numel (strfind (fileread (fullfile (sshd, "sshd.log")), "Accepted publickey"));
%!   assert (nlog >= 3, fileread (fullfile (sshd, "sshd.log")));
%!   assert (isequal (__table (fullfile (db, "table.csv")), T));
%!
%!   ## a remote job's Octave killed (kill -9) halfway through red-plastic (its
%!   ## fits are done, their renders are not): the run completes that material
%!   db = fullfile (out, "db-ssh-kill");
%!   jl = fullfile (out, "ssh-kill.joblog");
%!   statf = fullfile (out, "ssh-kill.status");
%!   [~, cmd] = __make (top, db, merl, via (jl), true);
%!   __bg (cmd, pidf, statf);
%!   sshpid = str2double (fileread (fullfile (sshd, "sshd.pid")));
%!   ## the material's one Octave process, once its fit record is written
%!   victim = @() __descendant (sshpid, 'repro_material \("red-plastic"');
%!   mdir = fullfile (db, "materials", "red-plastic");
%!   halfway = @() exist (fullfile (mdir, "fit", "red-plastic.json"), "file") == 2 ...
%!                 && exist (fullfile (mdir, "render", "red-plastic-fits.json"), "file") != 2;
%!   assert (__poll (@() halfway () && victim () > 0, 300), "no remote Octave had fitted red-plastic within 300 s");
%!   assert (system (sprintf ("kill -KILL %d", victim ())), 0);
%!   assert (__poll (@() exist (statf, "file") == 2, 600), "the run did not end within 600 s");
%!   log = fileread ([statf ".log"]);
%!   assert (str2double (fileread (statf)) == 0, "%s", log);
%!   J = __joblog (jl);
%!   k = strcmp (J(:,4), "red-plastic");
%!   assert (J{k,2} != 0 || J{k,3} != 0, "the killed job should have failed");
%!   assert (all ([J{! k,2}] == 0));
%!   assert (isequal (__table (fullfile (db, "table.csv")), T));
%!   assert (__partial (db), "");
%!   ## a rerun of the failed job (--resume-failed) finds nothing left to do
%!   [st, txt] = __make (top, db, merl, [via(jl) " PARALLEL_OPTS+=--resume-failed"]);
%!   assert (st == 0, "%s", txt);
%!   assert (isempty (regexp (txt, "fitting|rendering|POV-Ray render|held-out light")), txt);
%!   J = __joblog (jl);
%!   assert (J{end,4}, "red-plastic");
%!   assert ([J{end,2:3}], [0 0]);
%! unwind_protect_cleanup
%!   if (exist (pidf, "file"))
%!     system (sprintf ("kill -KILL -%d 2>/dev/null", str2double (fileread (pidf))));
%!     unlink (pidf);
%!   endif
%!   [st, txt] = __cluster (top, "sshd-stop", sshd);
%!   assert (st == 0, "%s", txt);
%! end_unwind_protect

%!test
%! ## Slurm: scripts/db_slurm_submit on a real single-node cluster
%! assert (! isempty (T), "the local run above failed");
%! slurm = fullfile (out, "slurm");
%! [st, txt] = __cluster (top, "slurm-start", slurm);
%! if (st == 2)
%!   printf ("skipped: the Slurm path: %s", txt);
%!   return;
%! endif
%! old = getenv ("SLURM_CONF");
%! setenv ("SLURM_CONF", fullfile (slurm, "slurm.conf"));
%! unwind_protect
%!   assert (st == 0, "%s", txt);
%!   logs = fullfile (out, "slurm-logs");
%!   submit = @(db) system (sprintf ("cd '%s' && SLURM_LOG_DIR='%s' scripts/db_slurm_submit DB='%s' MERL_DIR='%s' %s 2>&1",
%!                                   top, logs, db, merl, __opts ()));
%!   db = fullfile (out, "db-slurm");
%!   [st, txt] = submit (db);
%!   assert (st == 0, "%s", txt);
%!   id = regexp (txt, "job array (\\d+) \\(3 materials\\), merge job (\\d+)", "tokens", "once");
%!   assert (numel (id) == 2, "%s", txt);
%!   __check_bad_names (merl, txt);
%!   __slurm_wait (id, 600);
%!   merge = fileread (fullfile (logs, sprintf ("slurm-lafortune-db-merge-%s.out", id{2})));
%!   assert (! isempty (strfind (merge, "database: done")), merge);
%!   ## the array did every material; the merge job only wrote the report
%!   assert (isempty (regexp (merge, "fitting|rendering|POV-Ray render|held-out light")), merge);
%!   for t = 1:3
%!     task = fileread (fullfile (logs, sprintf ("slurm-lafortune-db-%s_%d.out", id{1}, t)));
%!     assert (! isempty (regexp (task, "\\[(green-metallic-paint|red-plastic|truncated)\\]")), task);
%!   endfor
%!   assert (isequal (__table (fullfile (db, "table.csv")), T));
%!
%!   ## task 1 (green-metallic-paint) cancelled halfway: after its fits, before its sheet
%!   db = fullfile (out, "db-slurm-cancel");
%!   [st, txt] = submit (db);
%!   assert (st == 0, "%s", txt);
%!   id = regexp (txt, "job array (\\d+) \\(3 materials\\), merge job (\\d+)", "tokens", "once");
%!   mat = fullfile (db, "materials", "green-metallic-paint");
%!   fitted = @() exist (fullfile (mat, "fit", "green-metallic-paint.json"), "file") == 2;
%!   assert (__poll (fitted, 300), "task 1 made no fit record within 300 s");
%!   assert (! exist (fullfile (mat, "sheet", "green-metallic-paint.json"), "file"),
%!           "task 1 finished before it could be cancelled");
%!   [st, txt] = system (sprintf ("scancel %s_1 2>&1", id{1}));
%!   assert (st == 0, "%s", txt);
%!   __slurm_wait (id, 600);
%!   task = fileread (fullfile (logs, sprintf ("slurm-lafortune-db-%s_1.out", id{1})));
%!   assert (! isempty (strfind (task, "CANCELLED")), task);
%!   ## the merge job did the rest of that material, and only of that one
%!   merge = fileread (fullfile (logs, sprintf ("slurm-lafortune-db-merge-%s.out", id{2})));
%!   ## (what was left: its renders, or, if the cancel came late, its held-out judging)
%!   assert (! isempty (regexp (merge, "\\[green-metallic-paint\\] (POV-Ray render|rendering|held-out light)")), merge);
%!   assert (isempty (regexp (merge, "\\[(red-plastic|truncated)\\]")), merge);
%!   assert (isequal (__table (fullfile (db, "table.csv")), T));
%!   assert (__partial (db), "");
%! unwind_protect_cleanup
%!   [st, txt] = __cluster (top, "slurm-stop", slurm);
%!   setenv ("SLURM_CONF", old);
%!   assert (st == 0, "%s", txt);
%! end_unwind_protect

%!test
%! ## the scratch folder of the blocks above
%! if (strncmp (out, tempdir (), numel (tempdir ())) && isfolder (out))
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (out, "s");
%! endif
