## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## A fuzz of the fitters (issue 49): the stiff and extreme tables of
## stability_cases (seeded) through every fitter of stability_run.  Each
## call gives a bounded, finite model (at most 10 times the data's largest
## finite value on the whole hemisphere) or an error with a lafortune: id;
## never a non-finite model, never an error without an id.  The cases and
## their outcomes are printed.  Bounded in time: each fit is bounded by its
## iteration limits; the whole run is checked against a generous limit.
## Run by `make check` (which sets LAFORTUNE_TOP); scripts/ on the path.

%!function top = __top ()
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! assert (exist (fullfile (top, "scripts", "stability_cases.m"), "file") == 2, "run from the project's top folder");
%!endfunction

%!test
%! addpath (fullfile (__top (), "scripts"));
%! C = stability_cases (1);
%! F = stability_run ();
%! n = zeros (1, 4);                     # bounded, error, defects, calls
%! defects = {};
%! t0 = tic ();
%! for i = 1:numel (C)
%!   for f = F
%!     r = stability_run (C(i).S, f{1});
%!     printf ("  %-38s %-7s %-16s %s\n", C(i).name, f{1}, r.what, r.id);
%!     n(4) += 1;
%!     switch (r.what)
%!       case "bounded"
%!         n(1) += 1;
%!       case "error"
%!         n(2) += 1;
%!       otherwise
%!         n(3) += 1;
%!         defects{end+1} = sprintf ("%s / %s: %s %s", C(i).name, f{1}, r.what, r.message);
%!     endswitch
%!   endfor
%! endfor
%! printf ("  %d cases x %d fitters: %d bounded, %d errors with an id, %d defects, %.0f s\n",
%!         numel (C), numel (F), n(1:3), toc (t0));
%! assert (n(4), numel (C) * numel (F));
%! assert (numel (C) >= 14);
%! assert (isempty (defects), strjoin (defects, "\n"));
%! assert (n(1) >= numel (C) * numel (F) / 2);  # most tables are fitted, not refused
%! assert (toc (t0) < 900);

%!test
%! ## the outcomes that must be as they are: the NaN and Inf tables and the
%! ## single sample refused with lafortune:badSamples; the channel of zeros
%! ## fitted as zero; the exploding start repaired
%! addpath (fullfile (__top (), "scripts"));
%! C = stability_cases (1);
%! names = {C.name};
%! for c = {"a NaN entry", "an Inf entry", "a single sample"}
%!   r = stability_run (C(strcmp (names, c{1})).S, "grow");
%!   assert ([r.what " " r.id], "error lafortune:badSamples");
%! endfor
%! r = stability_run (C(strcmp (names, "a channel of zeros")).S, "grow");
%! assert (r.what, "bounded");
%! assert (max (abs ([r.model.rho_d(3); r.model.Cxy(:,3); r.model.Cz(:,3)])), 0);
%! r = stability_run (C(1).S, "start");
%! assert (r.what, "bounded");
%! assert (r.ratio <= 10 + 1e-9);
