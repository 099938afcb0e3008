## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## The sampling's studies (issue 45) in their quick form: study_floor (the
## judge step's noise floor per material and density) and study_klights
## (K lights against the converged map), on the stand-ins.  Their tables
## are what the README and NEWS quote; these tests check that they are
## made of what they say.  Run by `make check` (which sets LAFORTUNE_TOP);
## scripts/ on the path.

%!function top = __top ()
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! assert (exist (fullfile (top, "scripts", "study_klights.m"), "file") == 2, "run from the project's top folder");
%!endfunction

%!test
%! ## more lights come closer to the map; the reference's own noise is below
%! ## every K-light error; one row per K and one for the reference (K = 0)
%! addpath (fullfile (__top (), "scripts"));
%! warning ("off", "lafortune:noLightProbe", "local");
%! T = study_klights ("", true);
%! for m = unique ({T.material})
%!   r = T(strcmp ({T.material}, m{1}));
%!   assert ([r.K], [0 16 64]);
%!   assert (r(3).flip < r(2).flip, sprintf ("%s: %g, %g", m{1}, r(2).flip, r(3).flip));
%!   assert (r(1).floor < r(3).flip);
%!   assert (r(3).relmse < r(2).relmse);
%!   assert (all ([r.time] > 0));
%! endfor

%!test
%! ## the floor is the FLIP between two renders with other seeds: in (0, 1)
%! ## for both densities, under every probe of JUDGE
%! addpath (fullfile (__top (), "scripts"));
%! warning ("off", "lafortune:noLightProbe", "local");
%! q = getenv ("QUICK");
%! unwind_protect
%!   T = study_floor ("", true);
%! unwind_protect_cleanup
%!   setenv ("QUICK", q);
%! end_unwind_protect
%! assert (sort (unique ({T.density})), {"fit", "table"});
%! assert (numel (T), 2 * 2 * 2);        # materials x densities x probes
%! assert (all ([T.floor] > 0 & [T.floor] < 1));
%! assert (all ([T.time_density] > 0));
