## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn {} {@var{F} =} fit_setup (@var{S}, @var{n0}, @var{keep}, @var{opt}, @var{fname})
## The metrics and scaled data of a fit (private), for both engines
## (fit_driver, for every type).  @var{S} is the checked table with a scene
## table's prior after row @var{n0}, @var{keep} the rows the fit sees.
## @var{F} has:
## @table @code
## @item Srep, rep, names
## the table as given (rows 1 .. @var{n0}) and its metrics as
## brdf_error defines them (fit_specs), in the data's units: what the
## fit reports;
## @item Sf
## the rows @var{keep};
## @item sc, iref
## the data's largest magnitude per channel, by which they are divided so
## that nothing in the fit depends on their units (with @code{"color",
## "shared"} one scale, the largest of @code{opt.channels}, whose position
## there is @var{iref}: the reference channel of shared lobes; [] else);
## @item Ss, fspec, pspec
## the scaled rows, the fit's metric on them (with the plain metric's delta
## of every row the fit sees, scaled) and the plain metric on them (data
## units).
## @end table
## @end deftypefn

function F = fit_setup (S, n0, keep, opt, fname)
  N = rows (S.wi);
  F.Srep = table_rows (S, (1:N)' <= n0);
  [F.rep, F.names] = fit_specs (F.Srep, opt.weight);
  pall = F.rep.plain;                   # plain, on every row the fit sees
  if (n0 < N)
    pall = metric_spec ("plain", S, fname);
  endif
  F.Sf = table_rows (S, keep);
  sc = max (abs (F.Sf.rgb), [], 1);
  F.iref = [];
  if (strcmp (opt.color, "shared"))
    [scmax, F.iref] = max (sc(opt.channels));
    sc(:) = scmax;
  endif
  sc(! (sc > 0)) = 1;
  F.sc = sc;
  F.Ss = F.Sf;
  F.Ss.rgb = F.Sf.rgb ./ sc;
  F.fspec = metric_spec (opt.weight, F.Ss, fname, pall.delta ./ sc);
  F.pspec = pall;
  if (! all (keep))
    F.pspec.w = pall.w(keep,:);
    F.pspec.ty = pall.ty(keep,:);
  endif
endfunction
