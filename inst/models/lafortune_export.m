## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} lafortune_export (@dots{})
## The former name of @code{brdf_export}, which it calls with the same
## arguments: kept so that scripts written for earlier versions keep
## working.  New code calls @code{brdf_export}, the name by what the
## function serves (every model type, not only Lafortune's).
##
## @example
## @group
## m = struct ("name", "demo", "rho_d", [0.1 0.05 0.02], "Cxy", [-1 -1 -1], ...
##             "Cz", [0.9 0.9 0.9], "e", [30 30 30]);
## lafortune_export (m, "demo.json");     # the same as brdf_export (m, "demo.json")
## @end group
## @end example
## @seealso{brdf_export}
## @end deftypefn
function lafortune_export (varargin)
  if (nargin == 0)
    print_usage ();
  endif
  brdf_export (varargin{:});
endfunction

%!test
%! m = struct ("name", "w", "rho_d", [0.1 0.2 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 30 40]);
%! d = tempname (); mkdir (d);
%! unwind_protect
%!   for f = {"w.json", "w.txt", "w.brdf"}
%!     lafortune_export (m, fullfile (d, ["a" f{1}]));
%!     brdf_export (m, fullfile (d, ["b" f{1}]));
%!     assert (isequal (fileread (fullfile (d, ["a" f{1}])), fileread (fullfile (d, ["b" f{1}]))));
%!   endfor
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect
%!error <Invalid call> lafortune_export ()
%!error <brdf_export: FILE .x.png. has the unknown extension> lafortune_export (struct ("rho_d", [0 0 0], "Cxy", zeros (0, 3), "Cz", zeros (0, 3), "e", zeros (0, 3)), "x.png")
