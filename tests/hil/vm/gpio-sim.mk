# gpio-sim out of tree, with kernel/irq/irq_sim.c linked in (Debian's kernels have neither).
obj-m := gpio-sim.o
gpio-sim-y := gpio-sim-core.o irq_sim.o
