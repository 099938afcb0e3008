## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{S}, @var{w}] =} check_table (@var{S}, @var{fname}, @var{nmin})
## The one check of a sample table (private), so that lafortune_fit and
## brdf_error accept the same tables: a struct with fields @code{wi},
## @code{wo} (unit directions, see check_dirs), @code{rgb} (real, finite,
## N x 3) and optionally @code{weight} (N values, finite, >= 0 and not all
## zero, as a row or a column; empty means none), with at least @var{nmin}
## samples.  @var{S} comes back with double directions and data, and its
## weight a column (removed when empty); @var{w} is the weight, ones when
## there is none.  Errors have the id @code{lafortune:badSamples} (and
## check_dirs' own) and name @var{fname}.
## @end deftypefn
function [S, w] = check_table (S, fname, nmin)
  if (! isstruct (S) || ! isscalar (S) || ! all (isfield (S, {"wi", "wo", "rgb"})))
    error ("lafortune:badSamples",
           "%s: S must be a struct with fields wi, wo, rgb (see merl_plane and merl_samples)",
           fname);
  endif
  [S.wi, S.wo] = __lafortune_check_dirs__ (S.wi, S.wo, fname);
  n = rows (S.wi);
  if (! isnumeric (S.rgb) || ! isreal (S.rgb) || ! isequal (size (S.rgb), [n 3]))
    error ("lafortune:badSamples", "%s: S.rgb must be real N x 3 with N = rows (S.wi) = %d",
           fname, n);
  endif
  if (! all (isfinite (S.rgb(:))))
    error ("lafortune:badSamples", "%s: S.rgb must be finite (drop invalid samples)", fname);
  endif
  if (n < nmin)
    error ("lafortune:badSamples", "%s: S needs at least %d samples, got %d", fname, nmin, n);
  endif
  S.rgb = double (S.rgb);
  w = ones (n, 1);
  if (isfield (S, "weight") && isempty (S.weight))
    S = rmfield (S, "weight");
  elseif (isfield (S, "weight"))
    w = S.weight;
    if (! isnumeric (w) || ! isreal (w) || ! isvector (w) || numel (w) != n
        || ! all (isfinite (w)) || any (w < 0) || ! any (w > 0))
      error ("lafortune:badSamples",
             "%s: S.weight must be N x 1 (N = %d), finite, >= 0 and not all zero", fname, n);
    endif
    w = double (w(:));
    S.weight = w;
  endif
endfunction
