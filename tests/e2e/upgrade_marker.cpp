// Test only: the plugin's library built a second time, for the upgrade test (upgrade_test.sh), as
// a new release would differ from the one installed. 64 KiB among its code move the code linked
// after them, so that the two libraries differ page by page; the exported label tells the test
// which of the two the plugin holds.
asm(".text\n"
    ".globl tsk_upgrade_marker\n"
    "tsk_upgrade_marker:\n"
    ".skip 65536\n");
