#!/usr/bin/env bash
# The grader's containment on cgroup v2, tried on a machine that has only
# v1 (as the course's own machines): Debian's kernel booted under qemu
# with cgroup v2 alone mounted, this machine's root file system shown
# read-only below a throw-away tmpfs, and the given test executables run
# there as root. By default: the runner's limits on the kernel
# (`sandbox::tests`) and the containment plants (`containment`,
# `containment_record`, `containment_nobody`), which must name v2 as the
# hierarchy whose limits held (XTASK_EXPECT_CGROUP=v2). Emulation is slow:
# the test that writes a GiB meets its time limit before its disk limit
# there (XTASK_EMULATED).
#
#   xtask/tests/cgroup-v2/run.sh            # from the course's root, as root
#
# Needs apt (qemu-system-x86, busybox-static, Debian's kernel package) and
# about 1.5 GB of disk in target/cgroup-v2. Under software emulation the
# containment plants take some minutes. Course only; not part of
# `cargo xtask test`.
set -euo pipefail
cd "$(dirname "$0")/../../.."
root=$(pwd)
work="$root/target/cgroup-v2"
mkdir -p "$work/share"

missing=""
command -v qemu-system-x86_64 > /dev/null || missing="qemu-system-x86"
{ ldd /bin/busybox 2>&1 || true; } | grep -q "not a dynamic" || missing="$missing busybox-static"
if [ -n "$missing" ]; then
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
fi

# Debian's kernel (cgroup v2 with every controller; 9p and overlayfs as
# modules, loaded by the init below).
if [ ! -d "$work/kernel/boot" ]; then
  package=$(apt-cache depends linux-image-amd64 | awk '/Depends: linux-image-[0-9]/ { print $2; exit }')
  (cd "$work" && apt-get download "$package" && dpkg-deb -x "$package"_*.deb kernel && rm "$package"_*.deb)
fi
vmlinuz=$(ls "$work"/kernel/boot/vmlinuz-*)
modules=$(ls -d "$work"/kernel/lib/modules/*)/kernel

# The initramfs: busybox, the modules, and an init that mounts the host's
# root through 9p (read-only) under an overlay whose writes go to a disk
# of their own (on a tmpfs, what tests write would count as memory that
# cannot be reclaimed, as it does not on a host's disk), cgroup v2 at
# /sys/fs/cgroup, and switches to it to run share/stage2.sh.
initrd="$work/initrd"
rm -rf "$initrd"
mkdir -p "$initrd"/{bin,lib/modules,proc,sys,dev,lower,upper,newroot}
cp /bin/busybox "$initrd/bin/busybox"
order="virtio virtio_ring virtio_pci_legacy_dev virtio_pci_modern_dev virtio_pci virtio_blk crc16 crc32c_generic mbcache jbd2 ext4 netfs fscache 9pnet 9pnet_virtio 9p overlay"
for module in $order; do
  find "$modules" -name "$module.ko" -exec cp {} "$initrd/lib/modules/" \;
done
cat > "$initrd/init" << EOF
#!/bin/busybox sh
/bin/busybox --install -s /bin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
# (In passes: which module needs which differs between kernel builds.)
for pass in 1 2 3 4 5; do
  for m in $order; do
    grep -q "^\$m " /proc/modules || insmod /lib/modules/\$m.ko 2> /dev/null || true
  done
done
for m in $order; do grep -q "^\$m " /proc/modules || echo "init: no module \$m"; done
mount -t 9p -o trans=virtio,version=9p2000.L,ro,msize=512000,cache=loose hostroot /lower
mount -t ext4 /dev/vda /upper
mkdir -p /upper/u /upper/w
mount -t overlay overlay -o lowerdir=/lower,upperdir=/upper/u,workdir=/upper/w /newroot
mount -t proc proc /newroot/proc
mount -t sysfs sys /newroot/sys
mount -t cgroup2 cgroup2 /newroot/sys/fs/cgroup
mount -t devtmpfs dev /newroot/dev
mkdir -p /newroot/dev/pts /newroot/dev/shm
mount -t devpts devpts /newroot/dev/pts
mount -t tmpfs tmpfs /newroot/dev/shm
mount -t tmpfs -o size=4G tmpfs /newroot/tmp
mount -t 9p -o trans=virtio,version=9p2000.L,msize=512000 share /newroot$work/share
echo "init: ready"
exec switch_root /newroot /bin/sh $work/share/stage2.sh
EOF
chmod +x "$initrd/init"
(cd "$initrd" && find . | busybox cpio -o -H newc 2> /dev/null | gzip -1 > "$work/initrd.gz")

# The test executables, built here; run there from xtask/ as cargo would.
built=$(cargo test -p xtask --bin xtask --test containment --test containment_record \
  --test containment_nobody --no-run 2>&1 | grep -o 'target/debug/deps/[a-z_]*-[0-9a-f]*' | sort -u)
{
  echo "export PATH=$PATH HOME=$HOME XTASK_EXPECT_CGROUP=v2 XTASK_EMULATED=1"
  # shellcheck disable=SC2016 # (expanded there)
  echo 'echo "kernel: $(uname -r)"; grep cgroup /proc/self/mountinfo'
  echo "cd $root/xtask"
  for executable in $built; do
    filter=""
    case "$executable" in */xtask-*) filter="sandbox::" ;; esac
    echo "echo '== $executable $filter'"
    echo "$root/$executable $filter --test-threads=1 --nocapture 2>&1 | tail -n 80"
  done
} > "$work/share/cmd.sh"
cat > "$work/share/stage2.sh" << EOF
/bin/bash $work/share/cmd.sh > $work/share/out.log 2>&1
sync
echo o > /proc/sysrq-trigger
sleep 10
EOF

rm -f "$work/share/out.log" "$work/upper.img"
truncate -s 24G "$work/upper.img"
mkfs.ext4 -q -F "$work/upper.img"
timeout "${VM_TIMEOUT:-3600}" qemu-system-x86_64 -accel tcg,thread=multi -cpu max -m 8G -smp 2 \
  -kernel "$vmlinuz" -initrd "$work/initrd.gz" \
  -append "console=ttyS0 panic=-1 loglevel=4" -nographic -no-reboot \
  -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap \
  -virtfs "local,path=$work/share,mount_tag=share,security_model=none" \
  -drive "file=$work/upper.img,format=raw,if=virtio,cache=unsafe" > "$work/boot.log" 2>&1 || true
rm -f "$work/upper.img"
cat "$work/share/out.log"
# Passed only when every executable said so.
[ "$(grep -c '^test result: ok' "$work/share/out.log")" = "$(echo "$built" | wc -w)" ]
