## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{file} =} bench_data (@var{name})
## @deftypefnx {} {[@var{file}, @var{brdf}, @var{src}] =} bench_data (@var{name}, @var{fallback}, @var{what})
## The MERL-format stand-in @var{name}.binary kept beside the project, for the
## benchmarks: in MERL_PROXY_DIR, else ../shared/data/merl-proxy; "" when
## absent (the benchmark then says what it uses instead).  With more outputs,
## also the material (read, or @var{fallback} () when absent) and the line
## that names it (@var{what} for the fallback).
## @end deftypefn
function [file, brdf, src] = bench_data (name, fallback, what)
  pd = getenv ("MERL_PROXY_DIR");
  if (isempty (pd))
    pd = fullfile (fileparts (mfilename ("fullpath")), "..", "..", "shared", "data", "merl-proxy");
  endif
  file = fullfile (pd, [name ".binary"]);
  if (! exist (file, "file"))
    file = "";
  endif
  if (nargout > 1)
    if (! isempty (file))
      brdf = merl_read (file);
      src = ["stand-in file " file];
    else
      brdf = fallback ();
      src = [what " (../shared absent)"];
    endif
  endif
endfunction
