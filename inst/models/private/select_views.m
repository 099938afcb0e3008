## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## V = select_views (S, fname): the training views of a table for the
## general fit (weight "select", both fronts): S.views of merl_samples, or
## an id'd error for a table without them
function V = select_views (S, fname)
  if (! (isstruct (S) && isscalar (S) && isfield (S, "views") && isstruct (S.views)
         && ! isempty (S.views)))
    error ("lafortune:badOption",
           ["%s: the weighting \"select\" (the general fit) needs a table with training views, " ...
            "as merl_samples (brdf) makes; give another weighting for this table"], fname);
  endif
  V = S.views;
endfunction
