% The certified H-infinity filter in MATLAB (or Octave): load the gains written by
%   build/bin/hinf-synth solve configs/paper-dbar0.05.yaml -o gains.mat
% into a state-space model of the filter y -> z_F and draw its singular values.
% MATLAB: Control System Toolbox.  Octave: pkg load control.
% Usage: gains_sigma('gains.mat')   (docs/file-formats.md "MATLAB files")
function F = gains_sigma(path)
  if nargin < 1, path = 'gains.mat'; end
  g = load(path);                      % variables named as in the YAML gains file
  if ~strcmp(g.format, 'hinf-gains/1'), error('%s is not a gains file (%s)', path, g.format); end
  f = g.filter;                        % A_F, B_F, C_F (and D_F, G_F when present)
  D = zeros(size(f.C_F, 1), size(f.B_F, 2));
  if isfield(f, 'D_F'), D = f.D_F; end
  T = 1;                               % a gains file without sample_time: one sample per unit
  if isfield(g, 'sample_time'), T = g.sample_time; end
  F = ss(f.A_F, f.B_F, f.C_F, D, T);   % x_F(k+1) = A_F x_F + B_F y, z_F = C_F x_F + D_F y
  fprintf('%s: %d states, gamma = %.17g (certified: %d)\n', path, size(f.A_F, 1), g.gamma, g.certificate.passed);
  sigma(F);
  title(sprintf('filter y -> z_F, certified gamma = %.6g', g.gamma));
end
