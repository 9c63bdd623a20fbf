# Sourced by a test that submits to Slurm: a one-node cluster on this machine, all its state
# under $1 (a scratch directory), its own munge key and socket and free ports, so it never
# meets a system's Slurm or munge. Exports SLURM_CONF for sbatch, squeue and scontrol.
# slurm_stop ends the three daemons (the caller traps it on exit).
slurm_dir=$1/slurm
mkdir -p "$slurm_dir"/{state,spool,log,munge}
chmod 700 "$slurm_dir/munge"

free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}
slurm_stop() {
    local pidfile pid
    for pidfile in "$slurm_dir"/slurmd.pid "$slurm_dir"/slurmctld.pid "$slurm_dir"/munge/munged.pid; do
        [ -s "$pidfile" ] || continue
        pid=$(cat "$pidfile")
        kill "$pid" 2> /dev/null || continue
        for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    done
}

# munged refuses a key readable by others, and a socket directory it does not own.
dd if=/dev/urandom of="$slurm_dir/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$slurm_dir/munge/munge.key"
munged --key-file="$slurm_dir/munge/munge.key" --socket="$slurm_dir/munge/socket" \
       --pid-file="$slurm_dir/munge/munged.pid" --log-file="$slurm_dir/log/munged.log" \
       --seed-file="$slurm_dir/munge/seed" --force

cores=$(nproc)
cat > "$slurm_dir/slurm.conf" <<CONF
ClusterName=picstudytest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$slurm_dir/munge/socket
CredType=cred/munge
StateSaveLocation=$slurm_dir/state
SlurmdSpoolDir=$slurm_dir/spool
SlurmctldPidFile=$slurm_dir/slurmctld.pid
SlurmdPidFile=$slurm_dir/slurmd.pid
SlurmctldLogFile=$slurm_dir/log/slurmctld.log
SlurmdLogFile=$slurm_dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MaxArraySize=10000
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cores State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$slurm_dir/slurm.conf
slurmctld -i -f "$SLURM_CONF"
slurmd -N localhost -f "$SLURM_CONF"
# The node registers within seconds; a job submitted before that waits for it anyway.
for _ in $(seq 100); do
    sinfo -h -o %t 2> /dev/null | grep -qE '^(idle|mix|alloc)' && break
    sleep 0.2
done
