# Sourced (". scripts/cuda-env.sh") before building against the CUDA Kokkos that
# `scripts/bootstrap.sh --cuda` installs: Kokkos 3.4's nvcc_wrapper must reach Debian's
# CUDA 11.8 nvcc with g++-11 as host compiler. Another toolkit earlier on PATH (such as
# a newer one in /usr/local/cuda, which Kokkos 3.4 cannot build with) is hidden.
unset CUDA_HOME CUDA_PATH CUDACXX LIBRARY_PATH
rouleau_clean_path=""
rouleau_old_ifs=$IFS
IFS=:
for rouleau_dir in $PATH; do
  if [ -x "$rouleau_dir/nvcc" ] && ! [ "$rouleau_dir/nvcc" -ef /usr/bin/nvcc ]; then continue; fi
  rouleau_clean_path="${rouleau_clean_path:+$rouleau_clean_path:}$rouleau_dir"
done
IFS=$rouleau_old_ifs
export PATH="$rouleau_clean_path"
unset rouleau_clean_path rouleau_old_ifs rouleau_dir
export CUDA_ROOT=/usr
export NVCC_WRAPPER_DEFAULT_COMPILER=g++-11
export NVCC_WRAPPER_DEFAULT_ARCH="${ROULEAU_CUDA_SM:-sm_80}"
