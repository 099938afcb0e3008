## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_mkdir (@var{d})
## Make the folder @var{d} (and its parents) unless it exists.  Steps of
## make -j run at once and may make the same folder (results/data for two
## materials): a folder that another process made meanwhile is no error;
## a folder that cannot be made is the error @code{lafortune:unwritable}.
## @end deftypefn
function repro_mkdir (d)
  if (isempty (d) || isfolder (d))
    return;
  endif
  ## a parent made meanwhile by another process fails this process's
  ## mkdir of its parents ("File exists"): then try again, the parent is there
  for attempt = 1:4
    [ok, msg] = mkdir (d);
    if (ok || isfolder (d))
      return;
    endif
  endfor
  error ("lafortune:unwritable", "cannot make the folder '%s': %s", d, msg);
endfunction
