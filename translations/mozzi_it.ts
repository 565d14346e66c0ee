<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it_IT" sourcelanguage="en_US">
<context>
    <name>Pages</name>
    <message>
        <location filename="../app/gui/builtin_pages.cpp" line="+52"/>
        <source>Cannot show the mesh: %1</source>
        <translation>Impossibile mostrare la mesh: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot place the mesh: %1</source>
        <translation>Impossibile posizionare la mesh: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%n trace line segment(s) name nodes the mesh does not have and are not drawn</source>
        <translation>
            <numerusform>%n segmento di linea di traccia cita nodi assenti dalla mesh e non viene disegnato</numerusform>
            <numerusform>%n segmenti di linea di traccia citano nodi assenti dalla mesh e non vengono disegnati</numerusform>
        </translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Overview</source>
        <translation>Panoramica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The open project: file, schema, specimens</source>
        <translation>Il progetto aperto: file, schema, provini</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>3-D View</source>
        <translation>Vista 3D</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The selected specimen&apos;s measurement mesh in 3-D</source>
        <translation>La mesh di misura del provino selezionato in 3D</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>FRF</source>
        <translation>FRF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnitude, phase and coherence of a stored FRF set</source>
        <translation>Modulo, fase e coerenza di un insieme di FRF memorizzato</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Could not read the FRF set: %1</source>
        <translation>Impossibile leggere l&apos;insieme di FRF: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Model vs Test</source>
        <translation>Modello contro prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnose where a model and a test disagree and which unmodelled effect explains it</source>
        <translation>Diagnostica dove modello e prova non concordano e quale effetto non modellato lo spiega</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Model vs test: %1</source>
        <translation>Modello contro prova: %1</translation>
    </message>
</context>
<context>
    <name>Parameters</name>
    <message>
        <location filename="../views/panels/parameter_texts.cpp" line="+15"/>
        <source>Actuator mode</source>
        <translation>Modalità dell&apos;attuatore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>slow triangular ramp or sine excitation (§1.1)</source>
        <translation>rampa triangolare lenta o eccitazione sinusoidale (§1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp peak force</source>
        <translation>Forza di picco della rampa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the actuator applies up to 5000 N statically (§1.1)</source>
        <translation>l&apos;attuatore applica staticamente fino a 5000 N (§1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp period</source>
        <translation>Periodo della rampa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one triangle -F -&gt; +F -&gt; -F; the generator&apos;s RAMP at 50% symmetry</source>
        <translation>un triangolo -F -&gt; +F -&gt; -F; la forma RAMP del generatore con simmetria al 50%</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sine frequency</source>
        <translation>Frequenza della sinusoide</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dynamic excitation from 1 to 45 Hz (§1.1)</source>
        <translation>eccitazione dinamica da 1 a 45 Hz (§1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sine force amplitude</source>
        <translation>Ampiezza della forza sinusoidale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set-point amplitude; the actuator&apos;s achievable amplitude falls with frequency (§1.1)</source>
        <translation>ampiezza del set-point; l&apos;ampiezza ottenibile dall&apos;attuatore diminuisce con la frequenza (§1.1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set-point scale</source>
        <translation>Scala del set-point</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>input scale of the actuator controller: 500 N/V maps +/-10 V onto +/-5000 N</source>
        <translation>scala d&apos;ingresso del controllore dell&apos;attuatore: 500 N/V porta +/-10 V su +/-5000 N</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Generator channel</source>
        <translation>Canale del generatore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output wired to the actuator controller&apos;s set-point input</source>
        <translation>uscita collegata all&apos;ingresso di set-point del controllore dell&apos;attuatore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On FIFO overrun</source>
        <translation>In caso di overrun della FIFO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>restart: clear the FIFO, report the gap and scan on; stop: end the session</source>
        <translation>restart: svuota la FIFO, segnala la lacuna e continua l&apos;acquisizione; stop: termina la sessione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transfer timeout</source>
        <translation>Timeout del trasferimento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a bulk transfer that brings no data for this long ends the session (at least twice its fill time)</source>
        <translation>un trasferimento bulk che per questo tempo non porta dati termina la sessione (almeno il doppio del suo tempo di riempimento)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Transfer length</source>
        <translation>Lunghezza del trasferimento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data per bulk transfer; four are queued, so about 400 ms of data are buffered on the host</source>
        <translation>dati per trasferimento bulk; quattro sono in coda, quindi circa 400 ms di dati restano nel buffer dell&apos;host</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Loop</source>
        <translation>Ciclo continuo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>start again at the end of the recording (until stop or the scan count)</source>
        <translation>ricomincia alla fine della registrazione (fino all&apos;arresto o al numero di scansioni)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Real-time pacing</source>
        <translation>Cadenza in tempo reale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deliver data at the pace of the (simulated or recorded) clock; off = as fast as the consumer takes it</source>
        <translation>fornisce i dati al ritmo del clock (simulato o registrato); disattivato = alla velocità con cui il consumatore li preleva</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Random seed</source>
        <translation>Seme casuale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>same seed, same data: noise, hit timing and faults are reproducible</source>
        <translation>stesso seme, stessi dati: rumore, istanti dei colpi e guasti sono riproducibili</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overrun probability per block</source>
        <translation>Probabilità di overrun per blocco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>each block is lost with this probability and reported as an overrun</source>
        <translation>ogni blocco va perso con questa probabilità ed è segnalato come overrun</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disconnect after</source>
        <translation>Disconnetti dopo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unplug the simulated device after this much data (0 = never)</source>
        <translation>scollega il dispositivo simulato dopo questa quantità di dati (0 = mai)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time out after</source>
        <translation>Timeout dopo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stop sending data after this much data, as a stalled transfer (0 = never)</source>
        <translation>smette di inviare dati dopo questa quantità di dati, come un trasferimento bloccato (0 = mai)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specimen</source>
        <translation>Provino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>virtual specimen with thesis modal parameters (Tables 6, 8, 11, 14, 16, 18, 19, 20; frames §2.1, §2.2)</source>
        <translation>provino virtuale con i parametri modali della tesi (Tabelle 6, 8, 11, 14, 16, 18, 19, 20; telai §2.1, §2.2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Hammer tip</source>
        <translation>Punta del martello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contact time pi sqrt(m/k): steel 0.3 ms, plastic 1 ms, rubber 3 ms</source>
        <translation>tempo di contatto pi sqrt(m/k): acciaio 0,3 ms, plastica 1 ms, gomma 3 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Peak force</source>
        <translation>Forza di picco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nominal peak of a hit (+/-10%)</source>
        <translation>picco nominale di un colpo (+/-10%)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time between hits</source>
        <translation>Tempo tra i colpi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one hit every so many seconds</source>
        <translation>intervallo in secondi tra un colpo e il successivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Force noise</source>
        <translation>Rumore sulla forza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>white noise RMS on the hammer</source>
        <translation>valore RMS del rumore bianco sul martello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response noise</source>
        <translation>Rumore sulla risposta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>white noise RMS on each accelerometer</source>
        <translation>valore RMS del rumore bianco su ogni accelerometro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Double-hit probability</source>
        <translation>Probabilità di doppio colpo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a hit rebounds (second contact at half the peak) with this probability</source>
        <translation>un colpo rimbalza (secondo contatto a metà del picco) con questa probabilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overload probability</source>
        <translation>Probabilità di sovraccarico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a hit is struck this many times harder than nominal with this probability</source>
        <translation>con questa probabilità un colpo è più forte del nominale di tante volte quanto il fattore di sovraccarico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Overload factor</source>
        <translation>Fattore di sovraccarico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>peak multiplier of an overloaded hit</source>
        <translation>moltiplicatore del picco di un colpo in sovraccarico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>virtual specimen with thesis static stiffness and twist axis (Tables 3, 4, 5, 7, 9, 10, 13)</source>
        <translation>provino virtuale con la rigidezza statica e l&apos;asse di torsione della tesi (Tabelle 3, 4, 5, 7, 9, 10, 13)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>up to 5000 N (§1.1); 0 = the thesis&apos;s range for the specimen (±300 N, fork B ±500 N, swing-arms 1000 N assumed)</source>
        <translation>fino a 5000 N (§1.1); 0 = l&apos;intervallo della tesi per il provino (±300 N, forcella B ±500 N, forcelloni 1000 N ipotizzati)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>0 -&gt; +F -&gt; -F -&gt; 0</source>
        <translation>0 -&gt; +F -&gt; -F -&gt; 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dynamic excitation up to 45 Hz (§1.1)</source>
        <translation>eccitazione dinamica fino a 45 Hz (§1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sine amplitude at 1 Hz</source>
        <translation>Ampiezza della sinusoide a 1 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>falls logarithmically with frequency to 20% at 45 Hz</source>
        <translation>diminuisce logaritmicamente con la frequenza fino al 20% a 45 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load-cell noise</source>
        <translation>Rumore della cella di carico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>white noise RMS on the load cell</source>
        <translation>valore RMS del rumore bianco sulla cella di carico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tyre</source>
        <translation>Pneumatico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one of the six thesis tyres (chapter 5, Tables 15-17)</source>
        <translation>uno dei sei pneumatici della tesi (capitolo 5, Tabelle 15-17)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inflation pressure</source>
        <translation>Pressione di gonfiaggio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>selects the contact half-length of Table 17 (interpolated)</source>
        <translation>sceglie la semilunghezza di contatto della Tabella 17 (interpolata)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical load</source>
        <translation>Carico verticale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 = the thesis test load (1500 N; 1000 N for the 12 inch tyres, §5.4)</source>
        <translation>0 = il carico di prova della tesi (1500 N; 1000 N per gli pneumatici da 12 pollici, §5.4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cornering stiffness</source>
        <translation>Rigidezza di deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 = 13 F_z /rad (assumed, core/tire/thesis_tyres.h)</source>
        <translation>0 = 13 F_z /rad (ipotizzata, core/tire/thesis_tyres.h)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Camber stiffness</source>
        <translation>Rigidezza di campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 = 0.9 F_z /rad (assumed)</source>
        <translation>0 = 0,9 F_z /rad (ipotizzata)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relaxation length</source>
        <translation>Lunghezza di rilassamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 = the thesis prediction of eq. 48 for this tyre and pressure</source>
        <translation>0 = la previsione della tesi (eq. 48) per questo pneumatico e questa pressione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Disk speed</source>
        <translation>Velocità del disco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>forward speed of the track under the tyre; the thesis tests ran at 5 km/h (§1.9)</source>
        <translation>velocità di avanzamento della pista sotto lo pneumatico; le prove della tesi si sono svolte a 5 km/h (§1.9)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Test</source>
        <translation>Prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonic yaw for the relaxation length (§1.9), or a steady side-slip or camber sweep</source>
        <translation>imbardata armonica per la lunghezza di rilassamento (§1.9), oppure una scansione quasi statica di deriva o di campanatura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Yaw amplitude</source>
        <translation>Ampiezza d&apos;imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonic yaw amplitude (§5.1: 1.5 deg)</source>
        <translation>ampiezza dell&apos;imbardata armonica (§5.1: 1,5 gradi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw frequencies</source>
        <translation>Frequenze d&apos;imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the step-increasing frequencies of §5.1; a trigger mark starts each</source>
        <translation>le frequenze crescenti a gradini del §5.1; un segnale di trigger avvia ciascuna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycles per frequency</source>
        <translation>Cicli per frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>about 10 cycles at each frequency (§5.1)</source>
        <translation>circa 10 cicli per ogni frequenza (§5.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw servo limit</source>
        <translation>Limite del servo d&apos;imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the machine reaches 10 deg; 6 deg by default against arm oscillations (§1.8)</source>
        <translation>la macchina raggiunge 10 gradi; 6 gradi per impostazione predefinita contro le oscillazioni del braccio (§1.8)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Camber servo limit</source>
        <translation>Limite del servo di campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the machine reaches 54 deg; 45 deg by default (§1.8)</source>
        <translation>la macchina raggiunge 54 gradi; 45 gradi per impostazione predefinita (§1.8)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slip sweep amplitude</source>
        <translation>Ampiezza della scansione di deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>side-slip triangle 0 -&gt; +max -&gt; -max -&gt; 0</source>
        <translation>triangolo di deriva 0 -&gt; +max -&gt; -max -&gt; 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Camber sweep amplitude</source>
        <translation>Ampiezza della scansione di campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>camber triangle 0 -&gt; +max -&gt; -max -&gt; 0</source>
        <translation>triangolo di campanatura 0 -&gt; +max -&gt; -max -&gt; 0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep period</source>
        <translation>Periodo della scansione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>slow enough to be quasi-static (sigma/V is about 0.1 s at 5 km/h)</source>
        <translation>abbastanza lento da essere quasi statico (sigma/V è circa 0,1 s a 5 km/h)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Camber during a slip sweep</source>
        <translation>Campanatura durante una scansione di deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slip during a camber sweep</source>
        <translation>Deriva durante una scansione di campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro noise</source>
        <translation>Rumore del giroscopio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Moment noise</source>
        <translation>Rumore sul momento</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+18"/>
        <source>Structural dynamics workbench</source>
        <translation>Banco di lavoro per la dinamica strutturale</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Project file to open</source>
        <translation>File di progetto da aprire</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save a screenshot of the window to FILE and quit.</source>
        <translation>Salva un&apos;immagine della finestra in FILE ed esci.</translation>
    </message>
</context>
<context>
    <name>mozzi::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+285"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New Project...</source>
        <translation>&amp;Nuovo progetto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open Project...</source>
        <translation>&amp;Apri progetto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open &amp;Recent</source>
        <translation>Apri &amp;recenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear List</source>
        <translation>Svuota elenco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save Project &amp;As...</source>
        <translation>Salva progetto &amp;come...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close Project</source>
        <translation>&amp;Chiudi progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Import</source>
        <translation>&amp;Importa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export</source>
        <translation>&amp;Esporta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work Area as &amp;Image...</source>
        <translation>Area di lavoro come &amp;immagine...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Universal File (UFF)...</source>
        <translation>File &amp;Universal (UFF)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Project</source>
        <translation>Progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Properties</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Reset Layout</source>
        <translation>&amp;Ripristina disposizione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Language</source>
        <translation>&amp;Lingua</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Pages</source>
        <translation>&amp;Pagine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Tools</source>
        <translation>&amp;Strumenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Create &amp;Demo Project...</source>
        <translation>Crea progetto &amp;dimostrativo...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check Project &amp;Integrity</source>
        <translation>Verifica &amp;integrità del progetto</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About Mozzi</source>
        <translation>&amp;Informazioni su Mozzi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>Informazioni su &amp;Qt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Property</source>
        <translation>Proprietà</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Mozzi</source>
        <translation>Mozzi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 - Mozzi</source>
        <translation>%1 - Mozzi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> [read-only]</source>
        <translation> [sola lettura]</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>Could not read the project.</source>
        <translation>Impossibile leggere il progetto.</translation>
    </message>
    <message>
        <location line="-106"/>
        <source>Where: %1</source>
        <translation>Dove: %1</translation>
    </message>
    <message>
        <location line="-276"/>
        <location line="+325"/>
        <source>Open Project</source>
        <translation>Apri progetto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not open %1.</source>
        <translation>Impossibile aprire %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened %1</source>
        <translation>Aperto %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read-only: %1</source>
        <translation>Sola lettura: %1</translation>
    </message>
    <message>
        <location line="-336"/>
        <location line="+342"/>
        <source>New Project</source>
        <translation>Nuovo progetto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not create %1.</source>
        <translation>Impossibile creare %1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Created %1</source>
        <translation>Creato %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Demo Project</source>
        <translation>Progetto dimostrativo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not create the demo project %1.</source>
        <translation>Impossibile creare il progetto dimostrativo %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Created demo project %1</source>
        <translation>Creato il progetto dimostrativo %1</translation>
    </message>
    <message>
        <location line="-345"/>
        <location line="+351"/>
        <source>Save Project As</source>
        <translation>Salva progetto come</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not save the project as %1.</source>
        <translation>Impossibile salvare il progetto come %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Saved a copy as %1 and opened it</source>
        <translation>Salvata una copia come %1 e aperta</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export Image</source>
        <translation>Esporta immagine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Could not write %1.</source>
        <translation>Impossibile scrivere %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Exported the work area to %1</source>
        <translation>Area di lavoro esportata in %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+11"/>
        <location line="+7"/>
        <source>Import</source>
        <translation>Importa</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Could not add a specimen for %1.</source>
        <translation>Impossibile aggiungere un provino per %1.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Could not import %1; the project is unchanged.</source>
        <translation>Impossibile importare %1; il progetto non è stato modificato.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Imported %1: %2 nodes, %3 lines, %4 FRFs, %5 modes</source>
        <translation>Importato %1: %2 nodi, %3 linee, %4 FRF, %5 modi</translation>
    </message>
    <message>
        <location line="-391"/>
        <source>Import Universal File</source>
        <translation>Importa file Universal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Universal files (*.uff *.unv);;All files (*)</source>
        <translation>File Universal (*.uff *.unv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+304"/>
        <source>Mozzi projects (*.mozzi)</source>
        <translation>Progetti Mozzi (*.mozzi)</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Mozzi projects (*.mozzi);;All files (*)</source>
        <translation>Progetti Mozzi (*.mozzi);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="-360"/>
        <source>A job stopped before its end; see its page</source>
        <translation>Un&apos;attività si è interrotta prima della fine; vedi la sua pagina</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Export Work Area</source>
        <translation>Esporta area di lavoro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG images (*.png);;JPEG images (*.jpg)</source>
        <translation>Immagini PNG (*.png);;Immagini JPEG (*.jpg)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Create Demo Project</source>
        <translation>Crea progetto dimostrativo</translation>
    </message>
    <message>
        <location line="+205"/>
        <source>Open in %1</source>
        <translation>Apri in %1</translation>
    </message>
    <message>
        <location line="+178"/>
        <source>Check Project Integrity</source>
        <translation>Verifica integrità del progetto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The project failed its integrity check.</source>
        <translation>Il progetto non ha superato la verifica di integrità.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Integrity check passed: %1</source>
        <translation>Verifica di integrità superata: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Integrity check passed</source>
        <translation>Verifica di integrità superata</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;h3&gt;Mozzi %1&lt;/h3&gt;&lt;p&gt;Structural dynamics workbench for two-wheeled-vehicle components: impact-hammer campaigns, stiffness rigs, tyre tests, modal and twist-axis identification, stability models.&lt;/p&gt;&lt;p&gt;Linked libraries:&lt;/p&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Mozzi %1&lt;/h3&gt;&lt;p&gt;Banco di lavoro per la dinamica strutturale dei componenti dei veicoli a due ruote: campagne con martello strumentato, banchi di rigidezza, prove pneumatici, identificazione modale e degli assi di torsione, modelli di stabilità.&lt;/p&gt;&lt;p&gt;Librerie collegate:&lt;/p&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>About Mozzi</source>
        <translation>Informazioni su Mozzi</translation>
    </message>
</context>
<context>
    <name>mozzi::views::FrfPlot</name>
    <message>
        <location filename="../views/plots/frf_plot.cpp" line="+132"/>
        <source>Unwrap phase</source>
        <translation>Fase continua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response / reference</source>
        <translation>Risposta / riferimento</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>receptance</source>
        <translation>recettanza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mobility</source>
        <translation>mobilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accelerance</source>
        <translation>inertanza</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnitude [dB]</source>
        <translation>Modulo [dB]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>|H| %1 [dB]</source>
        <translation>|H| %1 [dB]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Phase [deg]</source>
        <translation>Fase [gradi]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>magnitude</source>
        <translation>modulo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>phase</source>
        <translation>fase</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>coherence</source>
        <translation>coerenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coherence</source>
        <translation>Coerenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
</context>
<context>
    <name>mozzi::views::JobStatusWidget</name>
    <message numerus="yes">
        <location filename="../views/common/job_status_widget.cpp" line="+54"/>
        <source>(+%n more)</source>
        <translation>
            <numerusform>(+%n altra)</numerusform>
            <numerusform>(+%n altre)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop this job</source>
        <translation>Interrompi questa attività</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ModelTestView</name>
    <message>
        <location filename="../views/gap/model_test_view.cpp" line="+231"/>
        <source>Export Diagnosis Report</source>
        <translation>Esporta rapporto di diagnosi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HTML report (*.html)</source>
        <translation>Rapporto HTML (*.html)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Choose Model</source>
        <translation>Scegli il modello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Models (*.json *.uff *.unv);;All files (*)</source>
        <translation>Modelli (*.json *.uff *.unv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Choose Test Data</source>
        <translation>Scegli i dati di prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test data (*.uff *.unv *.csv *.json);;All files (*)</source>
        <translation>Dati di prova (*.uff *.unv *.csv *.json);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Choose a model file and a test file first.</source>
        <translation>Scegli prima un file di modello e un file di prova.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot use these files: %1</source>
        <translation>Impossibile usare questi file: %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 data, %2 residuals, %3 candidate effects at their locations.</source>
        <translation>Dati %1, %2 residui, %3 effetti candidati nelle loro posizioni.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Tick at least one candidate effect.</source>
        <translation>Seleziona almeno un effetto candidato.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Model vs test diagnosis</source>
        <translation>Diagnosi modello contro prova</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Diagnosing...</source>
        <translation>Diagnosi in corso...</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Diagnosis done.</source>
        <translation>Diagnosi completata.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The diagnosis stopped: %1</source>
        <translation>La diagnosi si è interrotta: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+167"/>
        <location line="+102"/>
        <source>Verdict: %1</source>
        <translation>Verdetto: %1</translation>
    </message>
    <message>
        <location line="-233"/>
        <location line="+139"/>
        <source>Item</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <location line="-139"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Significant</source>
        <translation>Significativo</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>yes</source>
        <translation>sì</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Effect</source>
        <translation>Effetto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Location</source>
        <translation>Posizione</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Size ± standard error</source>
        <translation>Entità ± errore standard</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Likelihood ratio</source>
        <translation>Rapporto di verosimiglianza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Threshold</source>
        <translation>Soglia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Held-out gain</source>
        <translation>Miglioramento sui dati esclusi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Shrink</source>
        <translation>Riduzione</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>(not identifiable)</source>
        <translation>(non identificabile)</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>model + %1</source>
        <translation>modello + %1</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+115"/>
        <source>model + best effect</source>
        <translation>modello + effetto migliore</translation>
    </message>
    <message>
        <location line="-105"/>
        <location line="+1"/>
        <source>Model vs test</source>
        <translation>Modello contro prova</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+79"/>
        <source>Model</source>
        <translation>Modello</translation>
    </message>
    <message>
        <location line="-79"/>
        <location line="+81"/>
        <source>Test</source>
        <translation>Prova</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>Gap before</source>
        <translation>Scarto iniziale</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gap</source>
        <translation>Scarto</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+79"/>
        <source>Ranked effects</source>
        <translation>Effetti in classifica</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Measured and model, before and after</source>
        <translation>Misura e modello, prima e dopo</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Nothing to export: run the diagnosis first.</source>
        <translation>Niente da esportare: esegui prima la diagnosi.</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+8"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>mozzi-model/1 JSON, UFF 55 modes, tyre or stability gap file</source>
        <translation>JSON mozzi-model/1, modi UFF 55, file di scarto pneumatico o stabilità</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UFF 58 FRFs, identified modes, relaxation lengths or stability frequencies</source>
        <translation>FRF UFF 58, modi identificati, lunghezze di rilassamento o frequenze di stabilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Band</source>
        <translation>Banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lowest frequency used (0 = from the first line)</source>
        <translation>Frequenza minima usata (0 = dalla prima riga)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest frequency used (0 = to the last line)</source>
        <translation>Frequenza massima usata (0 = fino all&apos;ultima riga)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bootstrap samples</source>
        <translation>Campioni bootstrap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated data sets that calibrate the false-attribution threshold</source>
        <translation>Insiemi di dati simulati che tarano la soglia delle false attribuzioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Multistarts</source>
        <translation>Partenze multiple</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Starting points of every nonlinear fit (more are slower and safer)</source>
        <translation>Punti di partenza di ogni stima non lineare (di più: più lento e più sicuro)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Candidate effects</source>
        <translation>Effetti candidati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load</source>
        <translation>Carica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run Diagnosis</source>
        <translation>Esegui diagnosi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export Report...</source>
        <translation>Esporta rapporto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where</source>
        <translation>Dove</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Overlay</source>
        <translation>Sovrapposizione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>measured</source>
        <translation>misura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>model</source>
        <translation>modello</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No diagnosis yet</source>
        <translation>Nessuna diagnosi</translation>
    </message>
</context>
<context>
    <name>mozzi::views::PageTabs</name>
    <message>
        <location filename="../views/common/page_tabs.cpp" line="+147"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ParameterForm</name>
    <message>
        <location filename="../views/panels/parameter_form.cpp" line="+246"/>
        <source>%1 %2 is outside %3 to %4 %2; %5 is used</source>
        <translation>%1 %2 è fuori dall&apos;intervallo da %3 a %4 %2; si usa %5</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+41"/>
        <source>Not accepted: %1</source>
        <translation>Non accettato: %1</translation>
    </message>
</context>
<context>
    <name>mozzi::views::PlotExport</name>
    <message>
        <location filename="../views/plots/plot_export.cpp" line="+59"/>
        <source>curve %1</source>
        <translation>curva %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>There is no plot to export.</source>
        <translation>Nessun grafico da esportare.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The plot shows no curve: nothing to write to %1.</source>
        <translation>Il grafico non mostra nessuna curva: niente da scrivere in %1.</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot export to %1: use a .png, .svg, .pdf or .csv file name.</source>
        <translation>Impossibile esportare in %1: usa un nome di file .png, .svg, .pdf o .csv.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot write %1: the folder does not exist.</source>
        <translation>Impossibile scrivere %1: la cartella non esiste.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot write %1 (the folder may be read-only).</source>
        <translation>Impossibile scrivere %1 (la cartella potrebbe essere in sola lettura).</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export Plot...</source>
        <translation>Esporta grafico...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this plot as PNG, SVG or PDF, or its curves as CSV</source>
        <translation>Salva questo grafico come PNG, SVG o PDF, oppure le sue curve come CSV</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+5"/>
        <source>Export Plot</source>
        <translation>Esporta grafico</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf);;CSV data (*.csv)</source>
        <translation>Immagine PNG (*.png);;Disegno SVG (*.svg);;Documento PDF (*.pdf);;Dati CSV (*.csv)</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ProjectOverview</name>
    <message>
        <location filename="../views/panels/project_overview.cpp" line="+97"/>
        <source>Specimen</source>
        <translation>Provino</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Description</source>
        <translation>Descrizione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No project open</source>
        <translation>Nessun progetto aperto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Create a project with File &gt; New, open one with File &gt; Open, or try the demo with Tools &gt; Create Demo Project.</source>
        <translation>Crea un progetto con File &gt; Nuovo, aprine uno con File &gt; Apri, oppure prova la dimostrazione con Strumenti &gt; Crea progetto dimostrativo.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>File: %1
Schema version %2, created %3 by Mozzi %4</source>
        <translation>File: %1
Versione dello schema %2, creato il %3 da Mozzi %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Opened read-only: %1</source>
        <translation>Aperto in sola lettura: %1</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ProjectTree</name>
    <message>
        <location filename="../views/common/project_tree.cpp" line="+82"/>
        <location line="+20"/>
        <source>Item</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <location line="-19"/>
        <location line="+19"/>
        <source>Count</source>
        <translation>Numero</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>none</source>
        <translation>nessuna</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 nodes, %2 lines</source>
        <translation>%1 nodi, %2 linee</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mesh</source>
        <translation>Mesh</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>File</source>
        <translation>File</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Access</source>
        <translation>Accesso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read-only: %1</source>
        <translation>sola lettura: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>read-write</source>
        <translation>lettura e scrittura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specimens</source>
        <translation>Provini</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+5"/>
        <location line="+10"/>
        <location line="+12"/>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <location line="-27"/>
        <location line="+5"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Description</source>
        <translation>Descrizione</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Notes</source>
        <translation>Note</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>FRF sets</source>
        <translation>Insiemi di FRF</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Source</source>
        <translation>Origine</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Frequency lines</source>
        <translation>Righe in frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response/reference pairs</source>
        <translation>Coppie risposta/riferimento</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modal results</source>
        <translation>Risultati modali</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Method</source>
        <translation>Metodo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Band</source>
        <translation>Banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 - %2 Hz</source>
        <translation>%1 - %2 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modes</source>
        <translation>Modi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data</source>
        <translation>Dati</translation>
    </message>
</context>
</TS>
