## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
## -*- texinfo -*-
## @deftypefn  {} {[@var{S}, @var{wt}, @var{n0}] =} fit_table (@var{S}, @var{weight}, @var{fname})
## @deftypefnx {} {[@var{model}, @var{models}] =} fit_table (@var{S}, @var{model}, @var{models})
## The table of a fit (private), for both fronts (lafortune_fit, brdf_fit):
## checked as brdf_error checks it (check_table), with a scene table's
## prior appended (fit_prior; its rows after row @var{n0}) and checked again
## with them, 4 samples at least; @var{wt} the weights.  With models, the
## table's name given to them (the exports carry it).
## @end deftypefn

function varargout = fit_table (S, arg2, arg3)
  if (isstruct (arg2))
    [varargout{1:2}] = name_models (S, arg2, arg3);
    return;
  endif
  [weight, fname] = deal (arg2, arg3);
  [S, wt] = check_table (S, fname, 1);
  [S, n0] = fit_prior (S, weight);
  if (n0 < rows (S.wi) || rows (S.wi) < 4)
    [S, wt] = check_table (S, fname, 4);
  endif
  varargout = {S, wt, n0};
endfunction

function [model, models] = name_models (S, model, models)
  if (isfield (S, "name") && ischar (S.name) && ! isempty (S.name))
    model.name = S.name;
    for k = 1:numel (models)
      models{k}.name = S.name;
    endfor
  endif
endfunction
