## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## The reports' tie rule (issue 45: every verdict states its noise): two
## fits of a material whose held-out FLIP differs by no more than its noise
## floor (repro_judge's FLIP between two renders of the measured data) tie.
##   - repro_tie, the one rule: within the floor, NaN floor (JUDGE empty);
##   - repro_models: the best model, and the models tied with it;
##   - db_verdicts: a FLIP rise with one more lobe within the floor is no
##     rise, above FAIL_FLIP_DROP or not;
##   - the template report_models: a tie is written beside the best model.
## Run by `make check` (which sets LAFORTUNE_TOP); scripts/ on the path.

%!function top = __top ()
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! assert (exist (fullfile (top, "scripts", "repro_tie.m"), "file") == 2, "run from the project's top folder");
%!endfunction

%!test
%! addpath (fullfile (__top (), "scripts"));
%! unwind_protect
%!   assert (repro_tie ([0.30 0.35 0.40], 0.30, 0.05), [true true false]);
%!   assert (repro_tie (0.3, 0.3, NaN), false);             # no floor measured: ranked as before
%!   assert (repro_tie (0.3, 0.3, 0), true);                # a deterministic render: equal values tie
%!   assert (repro_tie ([0.1; 0.5], [0.12 0.2], [0.05; 0.1]), [true false; false false]);
%!   fail ('repro_tie ("a", 1, 1)', "numeric");
%! unwind_protect_cleanup
%!   rmpath (fullfile (__top (), "scripts"));
%! end_unwind_protect

%!test
%! ## the best model and the models tied with it
%! addpath (fullfile (__top (), "scripts"));
%! unwind_protect
%!   c = struct ("methods", {{"inplane", "inplane_ggx", "general_ggx"}}, "models", {{"lafortune", "ggx"}},
%!               "lobes", [1 2]);
%!   F = struct ("inplane", [0.30 0.20; 0.50 0.40], "inplane_ggx", [0.32 0.10; 0.60 NaN],
%!               "general_ggx", [0.40 0.15; 0.70 0.41]);
%!   [M, B] = repro_models (c, F, [0.03; 0.005]);
%!   assert (B.model, {"lafortune", "ggx"; "lafortune", "lafortune"});
%!   assert (B.flip, [0.30 0.10; 0.50 0.40]);
%!   ## material 1: ggx 0.32 within 0.03 of 0.30 at 1 lobe; lafortune 0.20 not within 0.03 of 0.10
%!   ## material 2: ggx 0.41 not within 0.005 of 0.40
%!   assert (B.tied, {"lafortune, ggx", "ggx"; "lafortune", "lafortune"});
%!   [~, B0] = repro_models (c, F);                        # no floor: no tie
%!   assert (B0.tied, B0.model);
%!   [~, B1] = repro_models (c, F, [NaN; NaN]);
%!   assert (B1.tied, B1.model);
%! unwind_protect_cleanup
%!   rmpath (fullfile (__top (), "scripts"));
%! end_unwind_protect

%!test
%! ## a FLIP rise with a lobe counts only above FAIL_FLIP_DROP and the floor
%! addpath (fullfile (__top (), "scripts"));
%! unwind_protect
%!   c = struct ("methods", {{"general"}}, "materials", {{"a", "b", "c"}}, "lobes", [1 2],
%!               "fail_flip_drop", 0.02, "fail_flip", 0.5, "fail_flip_gain", 0.01);
%!   V = [0.20 0.25; 0.20 0.25; 0.20 0.21];               # rises 0.05, 0.05, 0.01
%!   X = struct ();
%!   X.flip = struct ("verdict", struct ("general", V), "pov", struct ("general", V));
%!   X.psnr = struct ("verdict", struct ("general", 30 * ones (3, 2)), "pov", struct ("general", 30 * ones (3, 2)));
%!   X.noise = [0.01; 0.08; NaN];                         # b: the rise is within its floor
%!   S = db_verdicts (c, 1:3, X, "rises");
%!   assert (S.verdict, {"a"});
%!   assert (S.in_sample, {"a", "b"});                     # in-sample: no floor
%!   assert (numel (S.verdict_steps), 1);
%!   assert (S.verdict_steps{1}.material, "a");
%!   S = db_verdicts (c, 1:3, X, "method", "general", struct ());
%!   assert (S.falls, {"a"});
%!   X.noise(:) = NaN;                                     # JUDGE empty: FAIL_FLIP_DROP alone
%!   S = db_verdicts (c, 1:3, X, "rises");
%!   assert (S.verdict, {"a", "b"});
%! unwind_protect_cleanup
%!   rmpath (fullfile (__top (), "scripts"));
%! end_unwind_protect

%!test
%! ## the template: a tie beside the best model of a material
%! addpath (fullfile (__top (), "scripts"));
%! unwind_protect
%!   f = fullfile (__top (), "scripts", "templates", "report_models.md");
%!   txt = fileread (f);
%!   row = regexp (txt, "\\{\\{#best_rows\\}\\}\n(.*?)\n\\{\\{/best_rows\\}\\}", "tokens", "once"){1};
%!   t = [tempname() ".md"];
%!   unwind_protect
%!     fid = fopen (t, "w");
%!     fputs (fid, ["{{#best_rows}}\n" row "\n{{/best_rows}}\n"]);
%!     fclose (fid);
%!     cells = struct ("has", {true, true}, "model", {"lafortune", "ggx"}, "flip", {0.3, 0.1},
%!                     "method", {"inplane", "inplane_ggx"}, "tie", {"lafortune, ggx", ""});
%!     V = struct ("best_rows", struct ("material", "m", "metal", false, "cells", cells));
%!     out = report_fill (t, V);
%!     assert (! isempty (strfind (out, "**lafortune** 0.300 (inplane), tie: lafortune, ggx |")), out);
%!     assert (! isempty (strfind (out, "| **ggx** 0.100 (inplane_ggx) |")), out);
%!   unwind_protect_cleanup
%!     unlink (t);
%!   end_unwind_protect
%! unwind_protect_cleanup
%!   rmpath (fullfile (__top (), "scripts"));
%! end_unwind_protect
