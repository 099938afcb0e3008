## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{e} =} lafortune_error (@dots{})
## The former name of @code{brdf_error}, which it calls with the same
## arguments: kept so that scripts written for earlier versions keep
## working.  New code calls @code{brdf_error}, the name by what the
## function serves (every model type, not only Lafortune's).
##
## @example
## @group
## m = struct ("rho_d", [0.1 0.1 0.1], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 20 20]);
## S = merl_plane (merl_standin ("red-plastic"));
## e = lafortune_error (m, S, "log");     # the same as brdf_error (m, S, "log")
## @end group
## @end example
## @seealso{brdf_error}
## @end deftypefn
function varargout = lafortune_error (varargin)
  if (nargin == 0)
    print_usage ();
  endif
  [varargout{1:max (nargout, 1)}] = brdf_error (varargin{:});
endfunction

%!test
%! m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 30 40]);
%! wi = [0.3 0 0.9; 0 0.5 0.8]; wo = [-0.3 0 0.9; 0.2 -0.4 0.9];
%! wi ./= vecnorm (wi, 2, 2); wo ./= vecnorm (wo, 2, 2);
%! S = struct ("wi", wi, "wo", wo, "rgb", [0.5 0.4 0.3; 0.2 0.2 0.2]);
%! [e1, i1] = lafortune_error (m, S, "log");
%! [e2, i2] = brdf_error (m, S, "log");
%! assert (isequal (e1, e2) && isequaln (rmfield (i1, "spec"), rmfield (i2, "spec")));
%! assert (isequal (lafortune_error (m, S), brdf_error (m, S)));
%!error <Invalid call> lafortune_error ()
%!error <MODEL must be a scalar struct> lafortune_error (1, 2)
