// SPDX-License-Identifier: BSD-2-Clause
// A qemu-user TCG plugin that counts the guest instructions a program executes and prints
// "insns N" when it exits. Debian 12's qemu-user (7.2) loads plugins (-plugin FILE) but
// ships neither the example plugins nor their header, so the few entry points used here
// are declared below, as QEMU 7.2 defines them (plugin API version 1).
//   cc -O2 -shared -fPIC -o insn-count.so toolchains/qemu-insn-count.c
//   qemu-aarch64 -plugin ./insn-count.so -L /usr/aarch64-linux-gnu PROGRAM ARGS...
// scripts/cross-insns.sh builds and uses it. Counts are summed over all guest threads
// without atomics: exact for single-threaded programs such as bench_detect.
#include <inttypes.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
struct qemu_info; // only passed by pointer here
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*tb_trans_fn)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*udata_fn)(qemu_plugin_id_t id, void *userdata);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, tb_trans_fn cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
					      void *ptr, uint64_t imm);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, udata_fn cb, void *userdata);
void qemu_plugin_outs(const char *string);

EXPORT int qemu_plugin_version = 1;

static uint64_t insns;

// Each translated block adds its instruction count to the total every time it runs.
static void translated(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
	(void)id;
	qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &insns,
						 qemu_plugin_tb_n_insns(tb));
}

static void finished(qemu_plugin_id_t id, void *userdata)
{
	(void)id;
	(void)userdata;
	char line[48];
	snprintf(line, sizeof line, "insns %" PRIu64 "\n", insns);
	qemu_plugin_outs(line);
}

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const struct qemu_info *info, int argc,
			       char **argv)
{
	(void)info;
	(void)argc;
	(void)argv;
	qemu_plugin_register_vcpu_tb_trans_cb(id, translated);
	qemu_plugin_register_atexit_cb(id, finished, NULL);
	return 0;
}
