## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{t} =} repro_tie (@var{a}, @var{b}, @var{floor})
## The one tie rule of the reports' verdicts: true where the held-out FLIP
## @var{a} and @var{b} of two fits differ by no more than the noise floor
## @var{floor} (repro_judge's @code{noise_flip_mean}: the FLIP between two
## renders of the measured data with different seeds; for fits judged
## against different references, the larger of their floors), so that the
## renders cannot rank them: the reports say they tie.  False where the
## floor is NaN (not measured: JUDGE empty, the verdicts in-sample) or a
## value is not finite.  The arguments broadcast (materials x lobes
## against materials x 1, say).
##
## @example
## repro_tie ([0.10 0.20], 0.105, 0.01)   # @result{} [1 0]
## @end example
## @end deftypefn
function t = repro_tie (a, b, floor)
  if (nargin != 3)
    print_usage ();
  endif
  if (! (isnumeric (a) && isnumeric (b) && isnumeric (floor)))
    error ("lafortune:badTie", "repro_tie: A, B and FLOOR must be numeric (FLIP values and the noise floor)");
  endif
  t = isfinite (a) & isfinite (b) & isfinite (floor) & abs (a - b) <= floor;
endfunction

%!assert (repro_tie ([0.10 0.20], 0.105, 0.01), [true false])
%!assert (repro_tie (0.1, 0.1, NaN), false)
%!assert (repro_tie (0.1, 0.1, 0), true)
%!assert (repro_tie ([0.1; 0.3], [0.11 0.5], [0.02; 0.1]), [true false; false false])
%!assert (repro_tie (NaN, 0.1, 1), false)
%!error <numeric> repro_tie ("a", 0.1, 0.1)
