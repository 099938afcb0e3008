## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} lafortune_import (@dots{})
## The former name of @code{brdf_import}, which it calls with the same
## arguments: kept so that scripts written for earlier versions keep
## working.  New code calls @code{brdf_import}, the name by what the
## function serves (every model type, not only Lafortune's).
##
## @example
## @group
## m = struct ("name", "demo", "rho_d", [0.1 0.05 0.02], "Cxy", [-1 -1 -1], ...
##             "Cz", [0.9 0.9 0.9], "e", [30 30 30]);
## brdf_export (m, "demo.json");
## m2 = lafortune_import ("demo.json");    # the same as brdf_import ("demo.json")
## @end group
## @end example
## @seealso{brdf_import}
## @end deftypefn
function varargout = lafortune_import (varargin)
  if (nargin == 0)
    print_usage ();
  endif
  [varargout{1:max (nargout, 1)}] = brdf_import (varargin{:});
endfunction

%!test
%! m = struct ("name", "w", "rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 30 40]);
%! f = [tempname() ".json"];
%! unwind_protect
%!   brdf_export (m, f);
%!   assert (isequal (lafortune_import (f), brdf_import (f), m));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect
%!error <Invalid call> lafortune_import ()
%!error <brdf_import: no such file> lafortune_import (tempname ())
