<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it_IT" sourcelanguage="en_US">
<context>
    <name>GapTerms</name>
    <message>
        <location filename="../views/gap/gap_terms.cpp" line="+18"/>
        <source>Modes</source>
        <translation>Modi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bands</source>
        <translation>Bande</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DOFs</source>
        <translation>GDL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Conditions</source>
        <translation>Condizioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Predictions</source>
        <translation>Previsioni</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FRF residual</source>
        <translation>Residuo FRF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mode residual</source>
        <translation>Residuo modale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Predicted f [Hz]</source>
        <translation>f prevista [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured f [Hz]</source>
        <translation>f misurata [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Predicted zeta</source>
        <translation>zeta prevista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured zeta</source>
        <translation>zeta misurata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>f error [%]</source>
        <translation>errore su f [%]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zeta error [%]</source>
        <translation>errore su zeta [%]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>f z</source>
        <translation>z di f</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zeta z</source>
        <translation>z di zeta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MAC</source>
        <translation>MAC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS residual</source>
        <translation>Residuo RMS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Noise floor</source>
        <translation>Fondo di rumore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chi2 per residual</source>
        <translation>chi2 per residuo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lines</source>
        <translation>Righe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured</source>
        <translation>Misurato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Predicted</source>
        <translation>Previsto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Uncertainty</source>
        <translation>Incertezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Found</source>
        <translation>Trovato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From [m/s]</source>
        <translation>Da [m/s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To [m/s]</source>
        <translation>A [m/s]</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>mass loading</source>
        <translation>massa aggiunta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>boundary stiffness</source>
        <translation>rigidezza di vincolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>element stiffness</source>
        <translation>rigidezza dell&apos;elemento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual mode</source>
        <translation>modo residuo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hysteretic damping</source>
        <translation>smorzamento isteretico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exponential window</source>
        <translation>finestra esponenziale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor misalignment</source>
        <translation>disallineamento del sensore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stiffness location</source>
        <translation>posizione della rigidezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bending stiffness</source>
        <translation>rigidezza flessionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inertia</source>
        <translation>inerzia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>residual compliance</source>
        <translation>cedevolezza residua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inertia error</source>
        <translation>errore di inerzia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>belt modes</source>
        <translation>modi della cintura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>carcass damping</source>
        <translation>smorzamento della carcassa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trail feedback</source>
        <translation>retroazione dell&apos;avancorsa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contact patch fraction</source>
        <translation>frazione dell&apos;impronta di contatto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ring pressure stiffening</source>
        <translation>irrigidimento dell&apos;anello con la pressione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fork bending</source>
        <translation>flessione della forcella</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fork torsion</source>
        <translation>torsione della forcella</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>tyre relaxation</source>
        <translation>rilassamento del pneumatico</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>all</source>
        <translation>tutto</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>mode %1 (%2 Hz)</source>
        <translation>modo %1 (%2 Hz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mode %1 (%2 Hz), unpaired</source>
        <translation>modo %1 (%2 Hz), non accoppiato</translation>
    </message>
</context>
<context>
    <name>KeptAnalyses</name>
    <message>
        <location filename="../views/common/kept_analyses.cpp" line="+20"/>
        <source>%1 (analysis %2)</source>
        <translation>%1 (analisi %2)</translation>
    </message>
</context>
<context>
    <name>Pages</name>
    <message numerus="yes">
        <location filename="../app/gui/builtin_pages.cpp" line="+74"/>
        <source>%n trace line segment(s) name nodes the mesh does not have and are not drawn</source>
        <translation>
            <numerusform>%n segmento di linea di traccia cita nodi assenti dalla mesh e non viene disegnato</numerusform>
            <numerusform>%n segmenti di linea di traccia citano nodi assenti dalla mesh e non vengono disegnati</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64"/>
        <source>FRFs</source>
        <translation>FRF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hits (time)</source>
        <translation>Colpi (tempo)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Overview</source>
        <translation>Panoramica</translation>
    </message>
    <message>
        <location line="+12"/>
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
        <location line="+31"/>
        <source>Stability</source>
        <translation>Stabilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Eigenvalues of a bicycle model against speed, its modes named and its critical speeds marked</source>
        <translation>Autovalori di un modello di bicicletta in funzione della velocità, con i modi nominati e le velocità critiche segnate</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Mesh Editor</source>
        <translation>Editor della mesh</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit a specimen&apos;s measurement mesh: nodes, lines, faces, DOFs</source>
        <translation>Modifica la mesh di misura di un provino: nodi, linee, facce, GDL</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Mode Animation</source>
        <translation>Animazione dei modi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Animate identified or imported modes on their mesh</source>
        <translation>Anima i modi identificati o importati sulla loro mesh</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Hammer Station</source>
        <translation>Stazione martello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run an impact campaign point by point: arm, hit, accept or reject</source>
        <translation>Esegue una campagna d&apos;impatto punto per punto: armare, colpire, accettare o scartare</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Stiffness Rig</source>
        <translation>Banco di rigidezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static and dynamic stiffness tests on the Motostiffmeter</source>
        <translation>Prove di rigidezza statica e dinamica sul Motostiffmeter</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Tyre Tester</source>
        <translation>Banco prova pneumatici</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relaxation and steady-state tests on the Mototiremeter</source>
        <translation>Prove di rilassamento e stazionarie sul Mototiremeter</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Identification</source>
        <translation>Identificazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identify modes on a stabilization diagram</source>
        <translation>Identifica i modi su un diagramma di stabilizzazione</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Twist Axes</source>
        <translation>Assi di torsione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The static and dynamic twist axes of stored stiffness-rig tests over the component&apos;s silhouette</source>
        <translation>Gli assi di torsione statico e dinamico delle prove al banco di rigidezza salvate, sulla sagoma del componente</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Stiffness</source>
        <translation>Rigidezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stiffness tables of the stored static rig tests, side by side across specimens, with the thesis&apos;s values</source>
        <translation>Tabelle di rigidezza delle prove statiche al banco memorizzate, affiancate per provino, con i valori della tesi</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Lumped Fork</source>
        <translation>Forcella a parametri concentrati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lumped fork models 1 to 3 against the measured modes, and the bicycle-fork stiffness and damping</source>
        <translation>Modelli di forcella a parametri concentrati da 1 a 3 a confronto con i modi misurati, e rigidezza e smorzamento della forcella da bicicletta</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Tyre Relaxation</source>
        <translation>Rilassamento pneumatico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relaxation length against frequency and pressure, the ring model&apos;s prediction and its contributions, the rigid-ring modes</source>
        <translation>Lunghezza di rilassamento in funzione della frequenza e della pressione, la previsione del modello ad anello e i suoi contributi, i modi ad anello rigido</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Wheelchair</source>
        <translation>Carrozzina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slalom and steady-turning trajectories and rear slip angles of the wheelchair model, with the tyre stiffness studies</source>
        <translation>Traiettorie in slalom e in curva stazionaria e angoli di deriva posteriori del modello di carrozzina, con gli studi sulla rigidezza degli pneumatici</translation>
    </message>
    <message>
        <location line="-266"/>
        <source>Could not read the FRF set: %1</source>
        <translation>Impossibile leggere l&apos;insieme di FRF: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>The open project: where to start, its specimens and what each holds</source>
        <translation>Il progetto aperto: da dove iniziare, i suoi provini e cosa contiene ciascuno</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The FRFs of a stored set: Bode, real and imaginary, Nyquist, coherence, sum and CMIF, with a cursor</source>
        <translation>Le FRF di un insieme memorizzato: Bode, parte reale e immaginaria, Nyquist, coerenza, somma e CMIF, con un cursore</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Model vs Test</source>
        <translation>Modello contro prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Diagnose where a model and a test disagree and which unmodelled effect explains it</source>
        <translation>Diagnostica dove modello e prova non concordano e quale effetto non modellato lo spiega</translation>
    </message>
    <message>
        <location line="+11"/>
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
        <source>Actuator set-point from</source>
        <translation>Riferimento dell&apos;attuatore da</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>internal: the rig&apos;s own drive (mode, static.*, sine.*); sim-funcgen: the simulated function generator (§1.1)</source>
        <translation>internal: il comando proprio del banco (mode, static.*, sine.*); sim-funcgen: il generatore di funzioni simulato (§1.1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Actuator set-point</source>
        <translation>Riferimento dell&apos;attuatore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sim-stiffness: the rig&apos;s own drive; sim-funcgen / usbtmc-funcgen: a function generator gives the actuator controller its set-point (§1.1)</source>
        <translation>sim-stiffness: il comando proprio del banco; sim-funcgen / usbtmc-funcgen: un generatore di funzioni fornisce il riferimento al controllore dell&apos;attuatore (§1.1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Laser positions</source>
        <translation>Posizioni dei laser</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>plate points u:v of lasers 1 to 4, separated by commas; empty = the specimen&apos;s plate layout</source>
        <translation>punti u:v della piastra dei laser da 1 a 4, separati da virgole; vuoto = la disposizione della piastra del provino</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load point</source>
        <translation>Punto di carico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>plate point u:v where the actuator loads; empty = the specimen&apos;s load point</source>
        <translation>punto u:v della piastra dove carica l&apos;attuatore; vuoto = il punto di carico del provino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plate width (u)</source>
        <translation>Larghezza della piastra (u)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the reference plate along u, centred on the load point where it is fixed to the specimen (§1.2)</source>
        <translation>la piastra di riferimento lungo u, centrata sul punto di carico dove è fissata al provino (§1.2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Plate height (v)</source>
        <translation>Altezza della piastra (v)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the reference plate along v, centred on the load point where it is fixed to the specimen (§1.2)</source>
        <translation>la piastra di riferimento lungo v, centrata sul punto di carico dove è fissata al provino (§1.2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Laser 1 u</source>
        <translation>Laser 1 u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 1 v</source>
        <translation>Laser 1 v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 2 u</source>
        <translation>Laser 2 u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 2 v</source>
        <translation>Laser 2 v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 3 u</source>
        <translation>Laser 3 u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 3 v</source>
        <translation>Laser 3 v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 4 u</source>
        <translation>Laser 4 u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Laser 4 v</source>
        <translation>Laser 4 v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where the laser&apos;s spot is on the plate, u = x (§1.2)</source>
        <translation>dove cade il punto del laser sulla piastra, u = x (§1.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where the laser&apos;s spot is on the plate, v = z (§1.2)</source>
        <translation>dove cade il punto del laser sulla piastra, v = z (§1.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load point u</source>
        <translation>Punto di carico u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load point v</source>
        <translation>Punto di carico v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where the actuator loads the specimen through the load cell (§1.1)</source>
        <translation>dove l&apos;attuatore carica il provino attraverso la cella di carico (§1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../views/rigs/rig_test_setup.cpp" line="+172"/>
        <source>Constrained end u</source>
        <translation>Estremità vincolata u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Constrained end v</source>
        <translation>Estremità vincolata v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where the specimen is locked to the rig&apos;s frame (§1.2)</source>
        <translation>dove il provino è bloccato al telaio del banco (§1.2)</translation>
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
    <message>
        <location line="+3"/>
        <source>Hammer point</source>
        <translation>Punto di battuta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DOF label of the mesh the hammer strikes, e.g. 12:+Y (-Y: struck the other way); empty = the specimen&apos;s driving point (the thesis&apos;s hammer point)</source>
        <translation>etichetta del GDL della mesh colpito dal martello, ad es. 12:+Y (-Y: colpito nel verso opposto); vuoto = il punto di eccitazione del provino (il punto di battuta della tesi)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Accelerometer DOFs</source>
        <translation>GDL degli accelerometri</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>comma-separated DOF labels of the mesh for acc 1..7 in order; empty = the first DOFs of the mesh; inputs without a DOF read noise only</source>
        <translation>etichette dei GDL della mesh per acc 1..7 in ordine, separate da virgole; vuoto = i primi GDL della mesh; gli ingressi senza GDL leggono solo rumore</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Constraint</source>
        <translation>Vincolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>how the specimen is held during the test (thesis §1.4)</source>
        <translation>come è vincolato il provino durante la prova (tesi §1.4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clamped nodes</source>
        <translation>Nodi incastrati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node labels held fixed, separated by spaces (clamped only)</source>
        <translation>etichette dei nodi tenuti fissi, separate da spazi (solo con incastro)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Constraint description</source>
        <translation>Descrizione del vincolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>in words, for the report: what is clamped and how</source>
        <translation>a parole, per il rapporto: cosa è incastrato e come</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Excitation</source>
        <translation>Eccitazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>roving hammer: one row of the FRF matrix; roving accelerometer: one column (thesis eq. 21)</source>
        <translation>martello mobile: una riga della matrice delle FRF; accelerometro mobile: una colonna (tesi, eq. 21)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fixed point</source>
        <translation>Punto fisso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fixed hammer (roving accelerometer) or reference accelerometer DOF, e.g. 3:+Y</source>
        <translation>il GDL del martello fisso (accelerometro mobile) o dell&apos;accelerometro di riferimento, ad es. 3:+Y</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sample rate</source>
        <translation>Frequenza di campionamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scans per second on every channel</source>
        <translation>scansioni al secondo su ogni canale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record length</source>
        <translation>Durata della registrazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>long enough for the response to die out</source>
        <translation>abbastanza lunga perché la risposta si estingua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pre-trigger</source>
        <translation>Pre-trigger</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fraction of the record kept before the trigger (common practice 10%)</source>
        <translation>frazione della registrazione conservata prima del trigger (prassi comune 10%)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trigger level</source>
        <translation>Livello di trigger</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force that starts a hit (rising slope on the hammer channel)</source>
        <translation>forza che avvia un colpo (fronte di salita sul canale del martello)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FRF band</source>
        <translation>Banda delle FRF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FRF lines stored up to here; 0 = sample rate / 2.56</source>
        <translation>righe delle FRF memorizzate fino a qui; 0 = frequenza di campionamento / 2,56</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Estimator</source>
        <translation>Stimatore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reject double hits</source>
        <translation>Scarta i doppi colpi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a second impact after the main pulse</source>
        <translation>un secondo impatto dopo l&apos;impulso principale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reject overloads</source>
        <translation>Scarta i sovraccarichi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a channel at the converter&apos;s full scale</source>
        <translation>un canale al fondo scala del convertitore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum peak force</source>
        <translation>Forza di picco minima</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force too low: a hit below this is rejected (0 = only the noise check)</source>
        <translation>forza troppo bassa: un colpo al di sotto di questo valore viene scartato (0 = solo il controllo del rumore)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum force SNR</source>
        <translation>SNR minimo della forza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>peak force over the pre-trigger noise</source>
        <translation>forza di picco rispetto al rumore di pre-trigger</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Minimum coherence</source>
        <translation>Coerenza minima</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>poor coherence: mean coherence of the point&apos;s average, from the second hit (0 = off)</source>
        <translation>coerenza scarsa: coerenza media della media del punto, dal secondo colpo (0 = disattivato)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Channel name</source>
        <translation>Nome del canale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>shown on the traces and in the report</source>
        <translation>mostrato sulle tracce e nel rapporto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transducer model</source>
        <translation>Modello del trasduttore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>e.g. PCB 086C03 (hammer), PCB M352C65 (accelerometer)</source>
        <translation>ad es. PCB 086C03 (martello), PCB M352C65 (accelerometro)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>Numero di serie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>of the transducer, for the calibration record</source>
        <translation>del trasduttore, per il registro di taratura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sensitivity</source>
        <translation>Sensibilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from the calibration sheet: mV per N (hammer) or per m/s^2 (accelerometer)</source>
        <translation>dal certificato di taratura: mV per N (martello) o per m/s^2 (accelerometro)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IEPE supply</source>
        <translation>Alimentazione IEPE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>constant-current supply on for this input</source>
        <translation>alimentazione a corrente costante attiva per questo ingresso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration date</source>
        <translation>Data di taratura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ISO 8601 date of the last calibration</source>
        <translation>data ISO 8601 dell&apos;ultima taratura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured DOF</source>
        <translation>GDL misurato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where it measures, e.g. 7:+Y (ignored on the roving channel)</source>
        <translation>dove misura, ad es. 7:+Y (ignorato sul canale mobile)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hits per point</source>
        <translation>Colpi per punto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accepted hits averaged at each point (thesis §1.6: five)</source>
        <translation>colpi accettati mediati in ogni punto (tesi §1.6: cinque)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>H1 (noise on the response), H2 (noise on the force) or Hv</source>
        <translation>H1 (rumore sulla risposta), H2 (rumore sulla forza) o Hv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonic yaw for the relaxation length (§1.9), a side-slip or camber sweep, or one held steady-state set-point (sweep.slip_deg, sweep.camber_deg; appendix 2)</source>
        <translation>imbardata armonica per la lunghezza di rilassamento (§1.9), una scansione di deriva o di campanatura, oppure un singolo set-point stazionario mantenuto (sweep.slip_deg, sweep.camber_deg; appendice 2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the machine reaches 55 deg (appendix 2; §1.8 prints 54); 45 deg by default (§1.8)</source>
        <translation>la macchina raggiunge 55 gradi (appendice 2; il §1.8 riporta 54); 45 gradi per impostazione predefinita (§1.8)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>also the held camber of a steady-state set-point</source>
        <translation>anche la campanatura mantenuta in un set-point stazionario</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>also the held side-slip of a steady-state set-point</source>
        <translation>anche la deriva mantenuta in un set-point stazionario</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>F of the ramp 0 -&gt; +F -&gt; -F -&gt; 0 (the thesis uses 300 N, fork B 500 N; §1.2)</source>
        <translation>F della rampa 0 -&gt; +F -&gt; -F -&gt; 0 (la tesi usa 300 N, forcella B 500 N; §1.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp duration</source>
        <translation>Durata della rampa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>time of the whole ramp; slow, so the specimen&apos;s inertia plays no part (§1.2)</source>
        <translation>durata dell&apos;intera rampa; lenta, così l&apos;inerzia del provino non ha alcun ruolo (§1.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequencies</source>
        <translation>Frequenze</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sine frequencies in the actuator&apos;s band of 1 to 45 Hz, separated by commas (§1.3)</source>
        <translation>frequenze delle sinusoidi nella banda dell&apos;attuatore da 1 a 45 Hz, separate da virgole (§1.3)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Force amplitude</source>
        <translation>Ampiezza della forza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sine set-point; the actuator&apos;s force falls with frequency (§1.1)</source>
        <translation>set-point sinusoidale; la forza dell&apos;attuatore diminuisce con la frequenza (§1.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settling cycles</source>
        <translation>Cicli di assestamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cycles discarded after the soft start (at least 1 s)</source>
        <translation>cicli scartati dopo l&apos;avvio graduale (almeno 1 s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recorded cycles</source>
        <translation>Cicli registrati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>whole cycles fitted with a sine per channel (at least 1 s)</source>
        <translation>cicli interi su cui si stima una sinusoide per canale (almeno 1 s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed of the rotating disk (the thesis runs the yaw test at 5 km/h, §1.9)</source>
        <translation>velocità del disco rotante (la tesi esegue la prova d&apos;imbardata a 5 km/h, §1.9)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>harmonic yaw frequencies, separated by commas (§5.1: 0.42 to 2.10 Hz)</source>
        <translation>frequenze dell&apos;imbardata armonica, separate da virgole (§5.1: da 0.42 a 2.10 Hz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>amplitude of the side-slip oscillation (§1.9: 1.5 deg)</source>
        <translation>ampiezza dell&apos;oscillazione di deriva (§1.9: 1,5 gradi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>yaw cycles recorded at each frequency (§5.1: about 10)</source>
        <translation>cicli d&apos;imbardata registrati a ogni frequenza (§5.1: circa 10)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cycles dropped at the start of each frequency (the lag&apos;s transient)</source>
        <translation>cicli scartati all&apos;inizio di ogni frequenza (il transitorio del ritardo)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>speed of the rotating disk (appendix 2)</source>
        <translation>velocità del disco rotante (appendice 2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side-slip set-points</source>
        <translation>Set-point di deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the side-slip sweep at zero camber, separated by commas (machine limit +/-10 deg)</source>
        <translation>la scansione di deriva a campanatura nulla, valori separati da virgole (limite della macchina +/-10 gradi)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Camber set-points</source>
        <translation>Set-point di campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the camber sweep at zero side-slip, separated by commas (machine limit +/-55 deg)</source>
        <translation>la scansione di campanatura a deriva nulla, valori separati da virgole (limite della macchina +/-55 gradi)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Settling time</source>
        <translation>Tempo di assestamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wait after each set-point before averaging (appendix 2 holds 10 s)</source>
        <translation>attesa dopo ogni set-point prima di mediare (l&apos;appendice 2 attende 10 s)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Averaging time</source>
        <translation>Tempo di media</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>forces and moments averaged per set-point</source>
        <translation>forze e momenti mediati per ogni set-point</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magic Formula fit</source>
        <translation>Stima della Magic Formula</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fit the Magic Formula to F_y and M_z at the end</source>
        <translation>stima la Magic Formula su F_y e M_z alla fine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Static bending stiffness</source>
        <translation>Rigidezza flessionale statica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from the static test and its decomposition (Table 10: 28 kNm/rad)</source>
        <translation>dalla prova statica e dalla sua scomposizione (Tabella 10: 28 kNm/rad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static axis arm L1</source>
        <translation>Braccio dell&apos;asse statico L1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where the static twist axis meets the fork axis, from the contact point (Table 12: 0.670 m)</source>
        <translation>dove l&apos;asse di torsione statico incontra l&apos;asse della forcella, dal punto di contatto (Tabella 12: 0.670 m)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Dynamic axis arm L2</source>
        <translation>Braccio dell&apos;asse dinamico L2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>where the modal twist axis meets the fork axis, from the contact point (Table 12: 0.846 m)</source>
        <translation>dove l&apos;asse di torsione modale incontra l&apos;asse della forcella, dal punto di contatto (Tabella 12: 0.846 m)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Wheel centre height</source>
        <translation>Altezza del centro ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel centre above the contact point (0.670 - 0.405 m, §4.2)</source>
        <translation>centro ruota sopra il punto di contatto (0.670 - 0.405 m, §4.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vibrating mass</source>
        <translation>Massa vibrante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel and unsprung mass (8 + 3 kg, §4.2)</source>
        <translation>ruota e massa non sospesa (8 + 3 kg, §4.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wheel inertia</source>
        <translation>Inerzia della ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the wheel&apos;s diametrical moment of inertia (0.278 kgm^2, §4.2)</source>
        <translation>momento d&apos;inerzia diametrale della ruota (0.278 kgm^2, §4.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured lateral mode</source>
        <translation>Modo laterale misurato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>natural frequency of the lateral mode with the wheel (Table 11: 22.3 Hz)</source>
        <translation>frequenza naturale del modo laterale con la ruota (Tabella 11: 22.3 Hz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Viscous damping ratio</source>
        <translation>Rapporto di smorzamento viscoso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>of that mode, as a fraction (Table 11: 2.4 %)</source>
        <translation>di quel modo, come frazione (Tabella 11: 2.4 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fork mass</source>
        <translation>Massa della forcella</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m_fork (Table 21: carbon 0.393, steel 1.336 kg)</source>
        <translation>m_fork (Tabella 21: carbonio 0.393, acciaio 1.336 kg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wheel mass</source>
        <translation>Massa della ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m_F (Table 21)</source>
        <translation>m_F (Tabella 21)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wheel radius</source>
        <translation>Raggio della ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>r_F (Table 21)</source>
        <translation>r_F (Tabella 21)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hub mass</source>
        <translation>Massa del mozzo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the fake hub of the fork-alone test (Table 21)</source>
        <translation>il finto mozzo della prova sulla sola forcella (Tabella 21)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hub radius</source>
        <translation>Raggio del mozzo</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>Table 21</source>
        <translation>Tabella 21</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Hub length</source>
        <translation>Lunghezza del mozzo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Blade-tip distance d</source>
        <translation>Distanza delle punte degli steli d</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>blade tips to the steering axis (eq. 52; not printed, 0.060 m assumed)</source>
        <translation>dalle punte degli steli all&apos;asse di sterzo (eq. 52; non pubblicata, assunta 0.060 m)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest bending arm</source>
        <translation>Braccio flessionale massimo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>h_W range upper end: the lower jaw fixing point (§6.5: 0.460 m)</source>
        <translation>estremo superiore di h_W: il punto di fissaggio della ganascia inferiore (§6.5: 0.460 m)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion mode with wheel</source>
        <translation>Modo torsionale con ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>Table 20, carbon fork</source>
        <translation>Tabella 20, forcella in carbonio</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Torsion loss factor with wheel</source>
        <translation>Fattore di perdita torsionale con ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hysteretic eta = 2 zeta (Table 20: 10.04 %)</source>
        <translation>eta isteretico = 2 zeta (Tabella 20: 10.04 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion mode, fork alone</source>
        <translation>Modo torsionale, sola forcella</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>Table 19, carbon fork</source>
        <translation>Tabella 19, forcella in carbonio</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Second torsion mode, fork alone</source>
        <translation>Secondo modo torsionale, sola forcella</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0 when the fork alone shows one torsion mode (steel fork: 230.1 Hz, eq. 54)</source>
        <translation>0 quando la sola forcella mostra un solo modo torsionale (forcella in acciaio: 230.1 Hz, eq. 54)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lateral mode with wheel</source>
        <translation>Modo laterale con ruota</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lateral loss factor with wheel</source>
        <translation>Fattore di perdita laterale con ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hysteretic eta = 2 zeta (Table 20: 4.24 %)</source>
        <translation>eta isteretico = 2 zeta (Tabella 20: 4.24 %)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lateral mode, fork alone</source>
        <translation>Modo laterale, sola forcella</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Manoeuvre</source>
        <translation>Manovra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stiffness study</source>
        <translation>Studio della rigidezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Forward speed</source>
        <translation>Velocità di avanzamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential torque</source>
        <translation>Coppia differenziale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slalom frequency</source>
        <translation>Frequenza dello slalom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration</source>
        <translation>Durata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torque ramp</source>
        <translation>Rampa di coppia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mass</source>
        <translation>Massa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw inertia</source>
        <translation>Inerzia di imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rear axle behind CoM</source>
        <translation>Asse posteriore dietro il baricentro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Casters ahead of CoM</source>
        <translation>Ruote pivottanti davanti al baricentro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rear half-track</source>
        <translation>Semicarreggiata posteriore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rear cornering stiffness</source>
        <translation>Rigidezza di deriva posteriore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rear aligning stiffness</source>
        <translation>Rigidezza di autoallineamento posteriore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>slalom: T_R - T_L = torque cos(2 pi f t); steady turning: the torque ramped up, then held (§7.3)</source>
        <translation>slalom: T_R - T_L = coppia cos(2 pi f t); curva stazionaria: la coppia cresce in rampa, poi resta costante (§7.3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the rear tyres&apos; cornering or aligning stiffness at 0.5, 1 and 2 times its value (Figures 57 to 60)</source>
        <translation>la rigidezza di deriva o di autoallineamento degli pneumatici posteriori a 0,5, 1 e 2 volte il suo valore (Figure da 57 a 60)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>held constant (§7.3); 4 km/h by default</source>
        <translation>mantenuta costante (§7.3); 4 km/h per impostazione predefinita</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T_R - T_L: the slalom&apos;s amplitude or the steady turn&apos;s held value</source>
        <translation>T_R - T_L: l&apos;ampiezza dello slalom o il valore mantenuto della curva stazionaria</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a manual slalom is below 1 Hz</source>
        <translation>uno slalom manuale è sotto 1 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>simulated time</source>
        <translation>tempo simulato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steady turning: time to reach the held torque</source>
        <translation>curva stazionaria: tempo per raggiungere la coppia mantenuta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>chair, user and rear wheels (assumed: 110 kg)</source>
        <translation>carrozzina, utente e ruote posteriori (assunta: 110 kg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>about the centre of mass</source>
        <translation>attorno al baricentro</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>b: distance of the rear axle behind the centre of mass (assumed)</source>
        <translation>b: distanza dell&apos;asse posteriore dietro il baricentro (assunta)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a_f: distance of the caster pivots ahead of the centre of mass (assumed)</source>
        <translation>a_f: distanza dei perni delle ruote pivottanti davanti al baricentro (assunta)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>w: half the distance between the rear wheels (assumed)</source>
        <translation>w: metà della distanza tra le ruote posteriori (assunta)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per rear tyre (10 F_z/rad at 400 N, §7.1)</source>
        <translation>per pneumatico posteriore (10 F_z/rad a 400 N, §7.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>per rear tyre (7.5 mm pneumatic trail)</source>
        <translation>per pneumatico posteriore (avancorsa pneumatica 7,5 mm)</translation>
    </message>
</context>
<context>
    <name>PlateSketch</name>
    <message>
        <location filename="../views/scene/plate_sketch.cpp" line="+146"/>
        <source>specimen&apos;s end</source>
        <translation>estremità del provino</translation>
    </message>
</context>
<context>
    <name>ReportDialog</name>
    <message>
        <location filename="../views/report/report_dialog.cpp" line="+28"/>
        <source>Project and specimens</source>
        <translation>Progetto e provini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency response functions</source>
        <translation>Funzioni di risposta in frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modal parameters</source>
        <translation>Parametri modali</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stiffness tests</source>
        <translation>Prove di rigidezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tyre tests</source>
        <translation>Prove sugli pneumatici</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gap diagnoses</source>
        <translation>Diagnosi dello scarto modello-prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stability against speed</source>
        <translation>Stabilità in funzione della velocità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wheelchair manoeuvres</source>
        <translation>Manovre della carrozzina</translation>
    </message>
</context>
<context>
    <name>ReportWriter</name>
    <message>
        <location filename="../views/report/report_writer.cpp" line="+38"/>
        <location filename="../views/report/stability_figures.cpp" line="+36"/>
        <source>the %1 view does not render in a project report</source>
        <translation>la vista %1 non si disegna in un rapporto di progetto</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Cannot create the folder %1</source>
        <translation>Impossibile creare la cartella %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot write %1</source>
        <translation>Impossibile scrivere %1</translation>
    </message>
</context>
<context>
    <name>RigResults</name>
    <message>
        <location filename="../views/rigs/rig_test_page.cpp" line="+112"/>
        <source>lateral stiffness k_lat</source>
        <translation>rigidezza laterale k_lat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twist arm a_tw</source>
        <translation>braccio di torsione a_tw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twist stiffness k_tw</source>
        <translation>rigidezza di torsione k_tw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twist axis inclination from the plate&apos;s v axis</source>
        <translation>inclinazione dell&apos;asse di torsione rispetto all&apos;asse v della piastra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twist axis foot from the load point, u</source>
        <translation>piede dell&apos;asse di torsione rispetto al punto di carico, u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twist axis foot from the load point, v</source>
        <translation>piede dell&apos;asse di torsione rispetto al punto di carico, v</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>peak force measured</source>
        <translation>forza di picco misurata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lateral stiffness, positive load</source>
        <translation>rigidezza laterale, carico positivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lateral stiffness, negative load</source>
        <translation>rigidezza laterale, carico negativo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rms residual of the laser plane</source>
        <translation>residuo rms del piano dei laser</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bending stiffness</source>
        <translation>rigidezza flessionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torsion stiffness</source>
        <translation>rigidezza torsionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bending arm</source>
        <translation>braccio flessionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torsion arm</source>
        <translation>braccio torsionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frequency</source>
        <translation>frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force amplitude</source>
        <translation>ampiezza della forza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frequencies with a twist axis</source>
        <translation>frequenze con un asse di torsione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lag of F_y behind the yaw angle</source>
        <translation>ritardo di F_y rispetto all&apos;angolo d&apos;imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>yaw amplitude</source>
        <translation>ampiezza d&apos;imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relaxation length</source>
        <translation>lunghezza di rilassamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>scatter of the relaxation length in the band</source>
        <translation>dispersione della lunghezza di rilassamento nella banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>frequencies in the band</source>
        <translation>frequenze nella banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disk speed</source>
        <translation>velocità del disco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contact half-length a (Table 17)</source>
        <translation>semilunghezza di contatto a (Tabella 17)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>side-slip set-point</source>
        <translation>set-point di deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>camber set-point</source>
        <translation>set-point di campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>side-slip angle measured</source>
        <translation>angolo di deriva misurato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>camber angle measured</source>
        <translation>angolo di campanatura misurato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lateral force F_y</source>
        <translation>forza laterale F_y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>yaw torque M_z</source>
        <translation>momento d&apos;imbardata M_z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>moment about the spin axis M_y</source>
        <translation>momento attorno all&apos;asse di rotazione M_y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cornering stiffness dF_y/dalpha</source>
        <translation>rigidezza di deriva dF_y/dalpha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>self-aligning torque stiffness dM_z/dalpha</source>
        <translation>rigidezza del momento di autoallineamento dM_z/dalpha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cornering stiffness / F_z</source>
        <translation>rigidezza di deriva / F_z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>camber stiffness dF_y/dgamma</source>
        <translation>rigidezza di campanatura dF_y/dgamma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twisting torque stiffness dM_z/dgamma</source>
        <translation>rigidezza del momento torcente dM_z/dgamma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magic Formula F_y rms residual</source>
        <translation>residuo rms della Magic Formula su F_y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magic Formula M_z rms residual</source>
        <translation>residuo rms della Magic Formula su M_z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>vertical load F_z</source>
        <translation>carico verticale F_z</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>laser %1 amplitude</source>
        <translation>ampiezza del laser %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>laser %1 phase from the force</source>
        <translation>fase del laser %1 rispetto alla forza</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magic Formula %1</source>
        <translation>Magic Formula %1</translation>
    </message>
</context>
<context>
    <name>StiffnessTablePage</name>
    <message>
        <location filename="../views/stiffness/stiffness_table_page.cpp" line="+51"/>
        <source>Lateral stiffness</source>
        <translation>Rigidezza laterale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Twist arm</source>
        <translation>Braccio di torsione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Twist stiffness</source>
        <translation>Rigidezza di torsione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending arm</source>
        <translation>Braccio flessionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending stiffness</source>
        <translation>Rigidezza flessionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion arm</source>
        <translation>Braccio torsionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion stiffness</source>
        <translation>Rigidezza torsionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination of the twist axis</source>
        <translation>Inclinazione dell&apos;asse di torsione</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>front-constrained</source>
        <translation>vincolato anteriormente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rear-constrained</source>
        <translation>vincolato posteriormente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steering head locked</source>
        <translation>cannotto di sterzo bloccato</translation>
    </message>
</context>
<context>
    <name>TwistAxesPage</name>
    <message>
        <location filename="../views/scene/plate_sketch.cpp" line="-9"/>
        <source>centre of gravity (estimated)</source>
        <translation>baricentro (stimato)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (constrained)</source>
        <translation>%1 (vincolato)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>L%1</source>
        <translation>L%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>load point (%1)</source>
        <translation>punto di carico (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>load point</source>
        <translation>punto di carico</translation>
    </message>
</context>
<context>
    <name>TwistAxesPoints</name>
    <message>
        <location line="-102"/>
        <source>steering head</source>
        <translation>cannotto di sterzo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>swing-arm pivot</source>
        <translation>perno del forcellone</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel hub</source>
        <translation>mozzo della ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel contact point</source>
        <translation>punto di contatto della ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheel axle</source>
        <translation>perno della ruota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dropouts</source>
        <translation>forcellini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>steerer tube</source>
        <translation>cannotto della forcella</translation>
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
        <location filename="../app/gui/main_window.cpp" line="+300"/>
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
        <location line="+2"/>
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
        <location line="+29"/>
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
        <location line="+68"/>
        <source>Cannot write the report: the renderer mozzi-report is not installed.</source>
        <translation>Impossibile scrivere il rapporto: il programma mozzi-report non è installato.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Report written: %1</source>
        <translation>Rapporto scritto: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The report was not written: %1</source>
        <translation>Il rapporto non è stato scritto: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Writing the report %1...</source>
        <translation>Scrittura del rapporto %1...</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Could not read the project.</source>
        <translation>Impossibile leggere il progetto.</translation>
    </message>
    <message>
        <location line="-106"/>
        <source>Where: %1</source>
        <translation>Dove: %1</translation>
    </message>
    <message>
        <location line="-351"/>
        <location line="+400"/>
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
        <location line="-411"/>
        <location line="+417"/>
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
        <location line="-420"/>
        <location line="+426"/>
        <source>Save Project As</source>
        <translation>Salva progetto come</translation>
    </message>
    <message>
        <location line="-255"/>
        <source>&amp;Report...</source>
        <translation>&amp;Relazione...</translation>
    </message>
    <message>
        <location line="+255"/>
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
        <location line="-466"/>
        <source>Import Universal File</source>
        <translation>Importa file Universal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Universal files (*.uff *.unv);;All files (*)</source>
        <translation>File Universal (*.uff *.unv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+379"/>
        <source>Mozzi projects (*.mozzi)</source>
        <translation>Progetti Mozzi (*.mozzi)</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Mozzi projects (*.mozzi);;All files (*)</source>
        <translation>Progetti Mozzi (*.mozzi);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="-435"/>
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
        <location line="+29"/>
        <source>Create Demo Project</source>
        <translation>Crea progetto dimostrativo</translation>
    </message>
    <message>
        <location line="+212"/>
        <source>Open in %1</source>
        <translation>Apri in %1</translation>
    </message>
    <message>
        <location line="+238"/>
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
    <name>mozzi::views</name>
    <message>
        <location filename="../views/report/report_figures_pages.cpp" line="+78"/>
        <source>the 3-D scene needs a display with OpenGL (Xvfb is enough); the %1 platform has none</source>
        <translation>la scena 3D richiede uno schermo con OpenGL (basta Xvfb); la piattaforma %1 non lo ha</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+97"/>
        <source>the 3-D scene has no OpenGL context on this display</source>
        <translation>la scena 3D non ha un contesto OpenGL su questo schermo</translation>
    </message>
    <message>
        <location line="-92"/>
        <source>the 3-D scene gave no picture</source>
        <translation>la scena 3D non ha prodotto alcuna immagine</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>no such mode</source>
        <translation>modo inesistente</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Mode %1</source>
        <translation>Modo %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the mode shape does not fit the mesh</source>
        <translation>la forma modale non corrisponde alla griglia</translation>
    </message>
    <message>
        <location filename="../views/report/report_figures_plots.cpp" line="+40"/>
        <source>the FRF set has no coherence</source>
        <translation>l&apos;insieme di FRF non ha la coerenza</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>the diagnosis is not stored in the project</source>
        <translation>la diagnosi non è conservata nel progetto</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the stored diagnosis holds no overlay curves</source>
        <translation>la diagnosi conservata non contiene curve da sovrapporre</translation>
    </message>
    <message>
        <location line="+10"/>
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
        <source>after: %1</source>
        <translation>dopo: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the tyre test has no measured points</source>
        <translation>la prova sullo pneumatico non ha punti misurati</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Slip angle [deg]</source>
        <translation>Angolo di deriva [gradi]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lateral force Fy [N]</source>
        <translation>Forza laterale Fy [N]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Aligning moment Mz [N m]</source>
        <translation>Momento autoallineante Mz [N m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fy</source>
        <translation>Fy</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mz</source>
        <translation>Mz</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the modal result names no FRF set</source>
        <translation>il risultato modale non indica alcun insieme di FRF</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the method draws no stabilization diagram</source>
        <translation>il metodo non traccia un diagramma di stabilizzazione</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>sum of |H| [dB]</source>
        <translation>somma di |H| [dB]</translation>
    </message>
</context>
<context>
    <name>mozzi::views::CampaignWizard</name>
    <message>
        <location filename="../views/campaign/campaign_wizard.cpp" line="+178"/>
        <source>New specimen: %1</source>
        <translation>Nuovo provino: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 hammer campaign</source>
        <translation>Campagna con martello %1</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>roving: the point being measured</source>
        <translation>mobile: il punto in misura</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>AI%1: %2</source>
        <translation>AI%1: %2</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>The campaign cannot be made: %1</source>
        <translation>Impossibile creare la campagna: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No project is open.</source>
        <translation>Nessun progetto aperto.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>virtual specimen %1</source>
        <translation>provino virtuale %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot add the specimen: %1</source>
        <translation>Impossibile aggiungere il provino: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cannot store the mesh: %1</source>
        <translation>Impossibile salvare la mesh: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>made with the new-campaign wizard</source>
        <translation>creata con la procedura guidata di nuova campagna</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot store the campaign: %1</source>
        <translation>Impossibile memorizzare la campagna: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>New Hammer Campaign</source>
        <translation>Nuova campagna con martello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specimen and station</source>
        <translation>Provino e stazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measurement mesh</source>
        <translation>Mesh di misura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Constraint</source>
        <translation>Vincolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Excitation</source>
        <translation>Eccitazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Transducers</source>
        <translation>Trasduttori</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acquisition and rejection rules</source>
        <translation>Acquisizione e regole di scarto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The specimen to test, its model in the simulated station, and the station. The campaign starts from the set-up of the thesis for that specimen; every later page can change it.</source>
        <translation>Il provino da provare, il suo modello nella stazione simulata e la stazione. La campagna parte dalla configurazione della tesi per quel provino; ogni pagina successiva può modificarla.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The template mesh the points come from. Untick the points you will not measure; they are measured in the order shown.</source>
        <translation>La mesh template da cui provengono i punti. Deseleziona i punti che non misurerai; vengono misurati nell&apos;ordine mostrato.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How the specimen is held during the test.</source>
        <translation>Come è vincolato il provino durante la prova.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roving hammer or roving accelerometer, the fixed point, and how many accepted hits each point averages.</source>
        <translation>Martello mobile o accelerometro mobile, il punto fisso e quanti colpi accettati vengono mediati in ogni punto.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The transducer on each input: model, serial, sensitivity from its calibration sheet, and where it measures.</source>
        <translation>Il trasduttore su ogni ingresso: modello, numero di serie, sensibilità dal suo certificato di taratura e dove misura.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>How each hit is recorded and which hits are rejected automatically; below, the station&apos;s own parameters.</source>
        <translation>Come viene registrato ogni colpo e quali colpi vengono scartati automaticamente; sotto, i parametri propri della stazione.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated hammer station (sim-hammer)</source>
        <translation>Stazione martello simulata (sim-hammer)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MCC USB-1608FS-Plus (real DAQ)</source>
        <translation>MCC USB-1608FS-Plus (DAQ reale)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station:</source>
        <translation>Stazione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Virtual specimen:</source>
        <translation>Provino virtuale:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Project specimen:</source>
        <translation>Provino del progetto:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Campaign name:</source>
        <translation>Nome della campagna:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The station driver&apos;s parameters</source>
        <translation>I parametri del driver della stazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station parameters (%1)</source>
        <translation>Parametri della stazione (%1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station parameters</source>
        <translation>Parametri della stazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plug the device in to see and set its parameters</source>
        <translation>Collega il dispositivo per vederne e impostarne i parametri</translation>
    </message>
</context>
<context>
    <name>mozzi::views::FrfPlot</name>
    <message>
        <location filename="../views/plots/frf_plot.cpp" line="+626"/>
        <source>Unwrap phase</source>
        <translation>Fase continua</translation>
    </message>
    <message>
        <location line="-301"/>
        <source>All responses</source>
        <translation>Tutte le risposte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All references</source>
        <translation>Tutti i riferimenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All points</source>
        <translation>Tutti i punti</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Response %1</source>
        <translation>Risposta %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reference %1</source>
        <translation>Riferimento %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Point %1</source>
        <translation>Punto %1</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>sum</source>
        <translation>somma</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CMIF %1</source>
        <translation>CMIF %1</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>No FRF matches the choice.</source>
        <translation>Nessuna FRF corrisponde alla scelta.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No FRF set.</source>
        <translation>Nessun insieme di FRF.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n FRF(s) shown (%1). Click a plot for a cursor; arrows step it, Shift+arrows pan, Ctrl+arrows or the wheel zoom, Home autoscales.</source>
        <translation>
            <numerusform>%n FRF mostrata (%1). Fai clic su un grafico per avere un cursore; le frecce lo spostano, Shift+frecce sposta la vista, Ctrl+frecce o la rotella fanno zoom, Home adatta automaticamente la scala.</numerusform>
            <numerusform>%n FRF mostrate (%1). Fai clic su un grafico per avere un cursore; le frecce lo spostano, Shift+frecce sposta la vista, Ctrl+frecce o la rotella fanno zoom, Home adatta automaticamente la scala.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>f = %1 Hz</source>
        <translation>f = %1 Hz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: |H| %2 (%3 dB), phase %4 deg, Re %5, Im %6</source>
        <translation>%1: |H| %2 (%3 dB), fase %4 gradi, Re %5, Im %6</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>and %n more</source>
        <translation>
            <numerusform>e altri %n</numerusform>
            <numerusform>e altri %n</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>nearest mode %1: %2 Hz (%3 Hz away)</source>
        <translation>modo più vicino %1: %2 Hz (a %3 Hz di distanza)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no identified mode</source>
        <translation>nessun modo identificato</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>m/N</source>
        <translation>m/N</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(m/s)/N</source>
        <translation>(m/s)/N</translation>
    </message>
    <message>
        <location line="+9"/>
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
        <location line="+10"/>
        <source>|H| [dB]</source>
        <translation>|H| [dB]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>|H|</source>
        <translation>|H|</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>|H| [%1]</source>
        <translation>|H| [%1]</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show</source>
        <translation>Mostra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bode</source>
        <translation>Bode</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Magnitude</source>
        <translation>Modulo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Phase</source>
        <translation>Fase</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Real and imaginary</source>
        <translation>Parte reale e immaginaria</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Phase, unwrapped [deg]</source>
        <translation>Fase continua [gradi]</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+3"/>
        <source>Re H</source>
        <translation>Re H</translation>
    </message>
    <message>
        <location line="-1"/>
        <location line="+5"/>
        <source>Im H</source>
        <translation>Im H</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>γ²</source>
        <translation>γ²</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coherence γ² (0 to 1)</source>
        <translation>Coerenza γ² (da 0 a 1)</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>Phase [deg]</source>
        <translation>Fase [gradi]</translation>
    </message>
    <message>
        <location line="-50"/>
        <source>(m/s²)/N</source>
        <translation>(m/s²)/N</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>|H| [dB re %1]</source>
        <translation>|H| [dB rif. %1]</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+28"/>
        <source>Coherence</source>
        <translation>Coerenza</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>Nyquist</source>
        <translation>Nyquist</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>dB</source>
        <translation>dB</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Linear</source>
        <translation>Lineare</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Logarithmic</source>
        <translation>Logaritmico</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Magnitude axis</source>
        <translation>Asse del modulo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Log frequency</source>
        <translation>Frequenza logaritmica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sum</source>
        <translation>Somma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Complex sum of the FRFs shown</source>
        <translation>Somma complessa delle FRF mostrate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CMIF</source>
        <translation>CMIF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Complex mode indicator function of the FRFs shown (singular values per line)</source>
        <translation>Funzione indicatrice dei modi complessi delle FRF mostrate (valori singolari per riga)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Autoscale</source>
        <translation>Scala automatica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit the axes to the curves (Home)</source>
        <translation>Adatta gli assi alle curve (Home)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response DOF</source>
        <translation>GDL di risposta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference DOF</source>
        <translation>GDL di riferimento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mesh point: FRFs whose response or reference is at this node</source>
        <translation>Punto della mesh: le FRF con risposta o riferimento in questo nodo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
</context>
<context>
    <name>mozzi::views::HammerStationPage</name>
    <message>
        <location filename="../views/campaign/hammer_station_events.cpp" line="+57"/>
        <source>Idle: press A to arm</source>
        <translation>Inattivo: premi A per armare</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Armed: hit the point</source>
        <translation>Armato: colpisci il punto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording the hit</source>
        <translation>Registrazione del colpo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict: Space accepts, Backspace rejects</source>
        <translation>Verdetto: Space accetta, Backspace scarta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Point done</source>
        <translation>Punto completato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waiting for the device</source>
        <translation>In attesa del dispositivo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Campaign finished</source>
        <translation>Campagna terminata</translation>
    </message>
    <message>
        <location filename="../views/campaign/hammer_station_page.cpp" line="+131"/>
        <source>New Campaign...</source>
        <translation>Nuova campagna...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start</source>
        <translation>Avvia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>Arresta</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Arm</source>
        <translation>Arma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disarm</source>
        <translation>Disarma</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Accept</source>
        <translation>Accetta</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reject</source>
        <translation>Scarta</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Redo Point</source>
        <translation>Ripeti punto</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Skip Point</source>
        <translation>Salta punto</translation>
    </message>
    <message>
        <location filename="../views/campaign/hammer_station_events.cpp" line="+241"/>
        <location filename="../views/campaign/hammer_station_page.cpp" line="+265"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../views/campaign/hammer_station_page.cpp" line="+45"/>
        <source>Next: %1</source>
        <translation>Prossimo: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Choose a campaign first, or make one with New Campaign (Ctrl+Shift+N).</source>
        <translation>Scegli prima una campagna, oppure creane una con Nuova campagna (Ctrl+Shift+N).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot open the campaign: %1</source>
        <translation>Impossibile aprire la campagna: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot start the campaign: %1</source>
        <translation>Impossibile avviare la campagna: %1</translation>
    </message>
    <message>
        <location filename="../views/campaign/hammer_station_events.cpp" line="+30"/>
        <location filename="../views/campaign/hammer_station_page.cpp" line="+16"/>
        <source>Force [%1]</source>
        <translation>Forza [%1]</translation>
    </message>
    <message>
        <location filename="../views/campaign/hammer_station_page.cpp" line="+4"/>
        <source>Campaign started on %1</source>
        <translation>Campagna avviata su %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Campaign stopped; every decided hit is in the project</source>
        <translation>Campagna arrestata; ogni colpo già deciso è nel progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped</source>
        <translation>Arrestata</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Open or create a project first.</source>
        <translation>Apri o crea prima un progetto.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>New campaign %1 created</source>
        <translation>Nuova campagna %1 creata</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Type why the point is skipped in the reason box, then press Enter.</source>
        <translation>Scrivi nella casella del motivo perché il punto viene saltato, poi premi Enter.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Point %1 skipped: %2</source>
        <translation>Punto %1 saltato: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Point %1 to be measured again</source>
        <translation>Punto %1 da misurare di nuovo</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Hammer station: %1</source>
        <translation>Stazione martello: %1</translation>
    </message>
    <message>
        <location filename="../views/campaign/hammer_station_events.cpp" line="-226"/>
        <source>TRIGGERED</source>
        <translation>TRIGGER SCATTATO</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+42"/>
        <source>ARMED</source>
        <translation>ARMATO</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>TRIGGER</source>
        <translation>TRIGGER</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+216"/>
        <source>Time since arming [s]</source>
        <translation>Tempo dall&apos;armamento [s]</translation>
    </message>
    <message>
        <location line="-198"/>
        <location line="+198"/>
        <source>Time in the hit&apos;s record [s]</source>
        <translation>Tempo nella registrazione del colpo [s]</translation>
    </message>
    <message>
        <location line="-186"/>
        <source>Hit point %1</source>
        <translation>Colpisci il punto %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The device went away; the campaign goes on when it is back.</source>
        <translation>Il dispositivo si è scollegato; la campagna riprende quando torna disponibile.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Point %1 (%2), hit attempt %3</source>
        <translation>Punto %1 (%2), tentativo di colpo %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>mean coherence %1</source>
        <translation>coerenza media %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GOOD HIT — Space accepts</source>
        <translation>COLPO VALIDO — Space accetta</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>REJECT: %1</source>
        <translation>DA SCARTARE: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>REJECT</source>
        <translation>DA SCARTARE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1. Backspace rejects, Space keeps it anyway. %2</source>
        <translation>%1. Backspace scarta, Spazio lo tiene comunque. %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>ACCEPTED</source>
        <translation>ACCETTATO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hit %1 stored at point %2 (%3)</source>
        <translation>Colpo %1 memorizzato nel punto %2 (%3)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Point %1: hit %2 accepted</source>
        <translation>Punto %1: colpo %2 accettato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>REJECTED</source>
        <translation>SCARTATO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Point %1: hit %2 rejected (%3)</source>
        <translation>Punto %1: colpo %2 scartato (%3)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>|H| [dB]</source>
        <translation>|H| [dB]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coh.</source>
        <translation>Coer.</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Point %1 (%2): running FRF of %n accepted hit(s)</source>
        <translation>
            <numerusform>Punto %1 (%2): FRF progressiva di %n colpo accettato</numerusform>
            <numerusform>Punto %1 (%2): FRF progressiva di %n colpi accettati</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+111"/>
        <source>Station: %1</source>
        <translation>Stazione: %1</translation>
    </message>
    <message>
        <location line="-108"/>
        <source>%1 of %2 points</source>
        <translation>%1 di %2 punti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2 done, %3 skipped; %4 hits accepted, %5 rejected</source>
        <translation>%1: %2 completati, %3 saltati; %4 colpi accettati, %5 scartati</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>skipped: %1</source>
        <translation>saltato: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>done</source>
        <translation>completato</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>measuring now</source>
        <translation>in misura</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>started</source>
        <translation>iniziato</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>to do</source>
        <translation>da fare</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%n attempt(s) at this point</source>
        <translation>
            <numerusform>%n tentativo in questo punto</numerusform>
            <numerusform>%n tentativi in questo punto</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Point %1 (%2)</source>
        <translation>Punto %1 (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>CAMPAIGN COMPLETE</source>
        <translation>CAMPAGNA COMPLETATA</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 points measured, %2 skipped; FRF set %3 stored with its hits</source>
        <translation>%1 punti misurati, %2 saltati; insieme di FRF %3 memorizzato con i suoi colpi</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Campaign finished: FRF set %1</source>
        <translation>Campagna terminata: insieme di FRF %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Arm again after each decision</source>
        <translation>Arma di nuovo dopo ogni decisione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Applies when the campaign starts</source>
        <translation>Si applica all&apos;avvio della campagna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response:</source>
        <translation>Risposta:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reason for Skip or Redo</source>
        <translation>Motivo per Salta o Ripeti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type the reason, then S skips the current point or R measures the selected point again</source>
        <translation>Scrivi il motivo, poi S salta il punto corrente o R misura di nuovo il punto selezionato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Point</source>
        <translation>Punto</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>DOF</source>
        <translation>GDL</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Hits</source>
        <translation>Colpi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Status</source>
        <translation>Stato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Force</source>
        <translation>Forza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response</source>
        <translation>Risposta</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>EU</source>
        <translation>EU</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>[%1]</source>
        <comment>right axis of the hit traces: the response&apos;s unit</comment>
        <translation>[%1]</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not started: choose a campaign, press F5</source>
        <translation>Non avviata: scegli una campagna, premi F5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station: not connected</source>
        <translation>Stazione: non collegata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The running FRF and coherence of the point appear after its first accepted hit.</source>
        <translation>La FRF progressiva e la coerenza del punto compaiono dopo il suo primo colpo accettato.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No point yet</source>
        <translation>Ancora nessun punto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The verdict of each hit appears here.</source>
        <translation>Il verdetto di ogni colpo compare qui.</translation>
    </message>
</context>
<context>
    <name>mozzi::views::HitTimeView</name>
    <message>
        <location filename="../views/plots/hit_time_view.cpp" line="+98"/>
        <source>hit %1</source>
        <translation>colpo %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hit %1 at %2</source>
        <translation>colpo %1 in %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cannot read the hit: %1</source>
        <translation>Impossibile leggere il colpo: %1</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Response [%1]</source>
        <translation>Risposta [%1]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>accepted</source>
        <translation>accettato</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rejected: %1</source>
        <translation>scartato: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>force window %1 ms (taper %2 ms)</source>
        <translation>finestra di forza %1 ms (raccordo %2 ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>exponential window tau %1 s</source>
        <translation>finestra esponenziale tau %1 s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rectangular windows</source>
        <translation>finestre rettangolari</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hit %1 at %2, %3 samples at %4 Hz, %5; %6</source>
        <translation>Colpo %1 in %2, %3 campioni a %4 Hz, %5; %6</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Hit:</source>
        <translation>Colpo:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Response:</source>
        <translation>Risposta:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time in the hit&apos;s record [s]</source>
        <translation>Tempo nella registrazione del colpo [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Force [N]</source>
        <translation>Forza [N]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force</source>
        <translation>forza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>response</source>
        <translation>risposta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force window (x peak force)</source>
        <translation>finestra di forza (x forza di picco)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>response window (x peak response)</source>
        <translation>finestra della risposta (x risposta di picco)</translation>
    </message>
</context>
<context>
    <name>mozzi::views::IdentificationPage</name>
    <message>
        <location filename="../views/modal/identification_page.cpp" line="+243"/>
        <source>Cannot list the FRF sets: %1</source>
        <translation>Impossibile elencare gli insiemi di FRF: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (id %2, %3 x %4 FRFs)</source>
        <translation>%1 (id %2, %3 x %4 FRF)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot read FRF set %1: %2</source>
        <translation>Impossibile leggere l&apos;insieme di FRF %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FRF set %1 holds no FRF to identify</source>
        <translation>L&apos;insieme di FRF %1 non contiene FRF da identificare</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot read the windows of FRF set %1: %2</source>
        <translation>Impossibile leggere le finestre dell&apos;insieme di FRF %1: %2</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>H %1 / %2</source>
        <translation>H %1 / %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>FRF set %1: %2 responses x %3 references, %4 lines, %5 to %6 Hz. Choose a band and run.</source>
        <translation>Insieme di FRF %1: %2 risposte x %3 riferimenti, %4 righe, da %5 a %6 Hz. Scegli una banda ed esegui.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Measured with an exponential window (tau = %1 s): its damping is removed from the modes.</source>
        <translation>Misurato con una finestra esponenziale (tau = %1 s): il suo smorzamento viene tolto dai modi.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Shown: the kept identification &apos;%1&apos; (%2, %3 .. %4 Hz), %n mode(s) and their synthesis; Run identifies again.</source>
        <translation>
            <numerusform>Mostrata: l&apos;identificazione conservata &apos;%1&apos; (%2, %3 .. %4 Hz), %n modo e la sua sintesi; Esegui identifica di nuovo.</numerusform>
            <numerusform>Mostrata: l&apos;identificazione conservata &apos;%1&apos; (%2, %3 .. %4 Hz), %n modi e la loro sintesi; Esegui identifica di nuovo.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Identifying %1 .. %2 Hz ...</source>
        <translation>Identificazione %1 .. %2 Hz ...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identification</source>
        <translation>Identificazione</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Identifying: %1</source>
        <translation>Identificazione: %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Identification cancelled.</source>
        <translation>Identificazione annullata.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identification failed: %1</source>
        <translation>Identificazione non riuscita: %1</translation>
    </message>
    <message>
        <location filename="../views/modal/identification_kept.cpp" line="+38"/>
        <location line="+114"/>
        <source>CMIF 1 [dB]</source>
        <translation>CMIF 1 [dB]</translation>
    </message>
    <message>
        <location line="-114"/>
        <location line="+114"/>
        <source>sum of |H| [dB]</source>
        <translation>somma di |H| [dB]</translation>
    </message>
    <message>
        <location line="-76"/>
        <source>These are the kept modes, in the project already: click poles or run to save other ones</source>
        <translation>Questi sono i modi conservati, già nel progetto: fai clic sui poli o esegui per salvarne altri</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Stabilization diagram</source>
        <translation>Diagramma di stabilizzazione</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>No stabilization diagram for the kept band of FRF set %1: %2</source>
        <translation>Nessun diagramma di stabilizzazione per la banda conservata dell&apos;insieme di FRF %1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/modal/identification_page.cpp" line="+18"/>
        <source>%n mode(s) selected automatically in %1 .. %2 Hz; click a pole to add or remove it.</source>
        <translation>
            <numerusform>%n modo selezionato automaticamente in %1 .. %2 Hz; fai clic su un polo per aggiungerlo o toglierlo.</numerusform>
            <numerusform>%n modi selezionati automaticamente in %1 .. %2 Hz; fai clic su un polo per aggiungerlo o toglierlo.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Refined on %L1 of %L2 band lines: those carrying the modes.</source>
        <translation>Raffinamento su %L1 delle %L2 linee della banda: quelle che portano i modi.</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>Identification of FRF set %1: %n mode(s)</source>
        <translation>
            <numerusform>Identificazione dell&apos;insieme di FRF %1: %n modo</numerusform>
            <numerusform>Identificazione dell&apos;insieme di FRF %1: %n modi</numerusform>
        </translation>
    </message>
    <message>
        <location line="+78"/>
        <location line="+9"/>
        <source>The chosen poles cannot be fitted: %1</source>
        <translation>Impossibile stimare i poli scelti: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Warning: %1. Remove one of the two.</source>
        <translation>Attenzione: %1. Togli uno dei due.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Cannot remove the exponential window&apos;s damping: %1</source>
        <translation>Impossibile togliere lo smorzamento della finestra esponenziale: %1</translation>
    </message>
    <message>
        <location filename="../views/modal/identification_synthesis.cpp" line="+36"/>
        <source>measured</source>
        <translation>misura</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>synthesised</source>
        <translation>sintesi</translation>
    </message>
    <message>
        <location filename="../views/modal/identification_page.cpp" line="+50"/>
        <location line="+7"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Nothing to save: run the identification and choose at least one pole.</source>
        <translation>Niente da salvare: esegui l&apos;identificazione e scegli almeno un polo.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Refining the selection before saving ...</source>
        <translation>Affinamento della selezione prima del salvataggio ...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Refine and save</source>
        <translation>Affina e salva</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Refinement failed, nothing saved: %1</source>
        <translation>Affinamento non riuscito, niente salvato: %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+15"/>
        <source>Cannot store the modes: %1</source>
        <translation>Impossibile memorizzare i modi: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>Saved %n mode(s) as modal result %1.</source>
        <translation>
            <numerusform>Salvato %n modo come risultato modale %1.</numerusform>
            <numerusform>Salvati %n modi come risultato modale %1.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modal result %1 saved from FRF set %2</source>
        <translation>Risultato modale %1 salvato dall&apos;insieme di FRF %2</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>FRF set</source>
        <translation>Insieme di FRF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Band</source>
        <translation>Banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lowest frequency of the band</source>
        <translation>Frequenza minima della banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest frequency of the band</source>
        <translation>Frequenza massima della banda</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Method</source>
        <translation>Metodo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pLSCF (PolyMAX)</source>
        <translation>pLSCF (PolyMAX)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LSCE</source>
        <translation>LSCE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Peak picking</source>
        <translation>Peak picking</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Circle fit</source>
        <translation>Circle fit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max order</source>
        <translation>Ordine max</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over</source>
        <translation>Sfondo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sum</source>
        <translation>Somma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CMIF</source>
        <translation>CMIF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>What the stabilization diagram is drawn over</source>
        <translation>La curva su cui è disegnato il diagramma di stabilizzazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refine</source>
        <translation>Affina</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Refine frequencies, damping and residues together after the automatic selection (standard errors; as mozzi-cli identify)</source>
        <translation>Affina insieme frequenze, smorzamenti e residui dopo la selezione automatica (errori standard; come mozzi-cli identify)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run</source>
        <translation>Esegui</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Automatic selection</source>
        <translation>Selezione automatica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back to the poles the automatic selection chose</source>
        <translation>Torna ai poli scelti dalla selezione automatica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name of the modal result</source>
        <translation>Nome del risultato modale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save modes</source>
        <translation>Salva modi</translation>
    </message>
    <message>
        <location filename="../views/modal/identification_kept.cpp" line="-50"/>
        <source>Refine the chosen poles and store them as a modal result of the project</source>
        <translation>Affina i poli scelti e li memorizza come risultato modale del progetto</translation>
    </message>
    <message>
        <location filename="../views/modal/identification_page.cpp" line="+2"/>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f [Hz]</source>
        <translation>f [Hz]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>std f [Hz]</source>
        <translation>std f [Hz]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>zeta</source>
        <translation>zeta</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>std zeta</source>
        <translation>std zeta</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>eta</source>
        <translation>eta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MPC</source>
        <translation>MPC</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>MPD [deg]</source>
        <translation>MPD [gradi]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Complexity</source>
        <translation>Complessità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FRF</source>
        <translation>FRF</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Residual [%]</source>
        <translation>Residuo [%]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Level [dB]</source>
        <translation>Livello [dB]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Misfit [dB]</source>
        <translation>Scarto [dB]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS of H - synthesis over the band against the FRF&apos;s own RMS</source>
        <translation>RMS di H - sintesi sulla banda rispetto all&apos;RMS della FRF stessa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS of the FRF over the band against the strongest FRF&apos;s (0 dB): a high residual far down is noise</source>
        <translation>RMS della FRF nella banda rispetto a quella della FRF più forte (0 dB): un residuo alto molto più in basso è rumore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS of H - synthesis against the strongest FRF&apos;s RMS (level + 20 log10 residual); the list is sorted by it, worst first</source>
        <translation>RMS di H - sintesi rispetto all&apos;RMS della FRF più forte (livello + 20 log10 residuo); l&apos;elenco è ordinato secondo questo valore, il peggiore per primo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Synthesis</source>
        <translation>Sintesi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MAC</source>
        <translation>MAC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>AutoMAC of the chosen modes</source>
        <translation>AutoMAC dei modi scelti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MAC: chosen modes (rows) against the automatic selection (columns)</source>
        <translation>MAC: modi scelti (righe) contro la selezione automatica (colonne)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>|H| [dB]</source>
        <translation>|H| [dB]</translation>
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
    <name>mozzi::views::LumpedForkPage</name>
    <message>
        <location filename="../views/stiffness/lumped_fork_page.cpp" line="+248"/>
        <source>Keep for specimen:</source>
        <translation>Conserva per il provino:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compute</source>
        <translation>Calcola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit the three lumped models and the bicycle fork from the forms</source>
        <translation>Identifica i tre modelli a parametri concentrati e la forcella da bicicletta dai moduli</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured modes:</source>
        <translation>Modi misurati:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use the selected mode</source>
        <translation>Usa il modo selezionato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Take the selected mode&apos;s frequency and damping ratio as the measured lateral mode</source>
        <translation>Prende frequenza e smorzamento del modo selezionato come modo laterale misurato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the models in the project</source>
        <translation>Conserva i modelli nel progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep in the project</source>
        <translation>Conserva nel progetto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bold: computed by the model; the other values come from the inputs (the dotted entries of thesis Table 12). Values to six significant digits, as mozzi-cli fork prints them.</source>
        <translation>In grassetto: calcolato dal modello; gli altri valori vengono dai dati di ingresso (le voci con il punto della Tabella 12 della tesi). Valori a sei cifre significative, come li stampa mozzi-cli fork.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>h_W is where the bending stiffness computed with the wheel (eq. 58) equals the one of the fork alone (eq. 59); c = zeta c_c with zeta = eta / 2 (eq. 55, 56, 60).</source>
        <translation>h_W è dove la rigidezza flessionale calcolata con la ruota (eq. 58) è uguale a quella della sola forcella (eq. 59); c = zeta c_c con zeta = eta / 2 (eq. 55, 56, 60).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Motorcycle fork (§4.2, Table 12)</source>
        <translation>Forcella motociclistica (§4.2, Tabella 12)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bicycle fork (§6.4, §6.5)</source>
        <translation>Forcella da bicicletta (§6.4, §6.5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending arm h_W from the blade tips [m]</source>
        <translation>Braccio flessionale h_W dalle punte degli steli [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>k_β(h_W) [Nm/rad]</source>
        <translation>k_β(h_W) [Nm/rad]</translation>
    </message>
    <message numerus="yes">
        <location line="+45"/>
        <source>%1: %2 (%n mode(s))</source>
        <translation>
            <numerusform>%1: %2 (%n modo)</numerusform>
            <numerusform>%1: %2 (%n modi)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Computing the lumped models...</source>
        <translation>Calcolo dei modelli a parametri concentrati...</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The computation stopped: %1</source>
        <translation>Il calcolo si è interrotto: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Lumped fork models</source>
        <translation>Modelli di forcella a parametri concentrati</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Lumped models: %1</source>
        <translation>Modelli a parametri concentrati: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bicycle fork torsion: %1</source>
        <translation>Torsione della forcella da bicicletta: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bicycle fork bending: %1</source>
        <translation>Flessione della forcella da bicicletta: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Computed.</source>
        <translation>Calcolato.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Bending stiffness k_i [Nm/rad]</source>
        <translation>Rigidezza flessionale k_i [Nm/rad]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending arm L_i [m]</source>
        <translation>Braccio flessionale L_i [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vibrating inertia J_i [kgm²]</source>
        <translation>Inerzia vibrante J_i [kgm²]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pure moment of inertia [kgm²]</source>
        <translation>Momento d&apos;inerzia puro [kgm²]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Natural frequency f_n [Hz]</source>
        <translation>Frequenza naturale f_n [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Damping coefficient c_i [Nms/rad]</source>
        <translation>Coefficiente di smorzamento c_i [Nms/rad]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Viscous damping ζ_i</source>
        <translation>Smorzamento viscoso ζ_i</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Model 1</source>
        <translation>Modello 1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model 2</source>
        <translation>Modello 2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model 3</source>
        <translation>Modello 3</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>f [Hz]</source>
        <translation>f [Hz]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ζ</source>
        <translation>ζ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model 1 f_n - f</source>
        <translation>Modello 1 f_n - f</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model 2 f_n - f</source>
        <translation>Modello 2 f_n - f</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model 3 f_n - f</source>
        <translation>Modello 3 f_n - f</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Measured modes</source>
        <translation>Modi misurati</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Model %1</source>
        <translation>Modello %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Torsion inertia with wheel [kgm²]</source>
        <translation>Inerzia torsionale con ruota [kgm²]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion inertia, fork alone [kgm²]</source>
        <translation>Inerzia torsionale, sola forcella [kgm²]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion stiffness with wheel [Nm/rad]</source>
        <translation>Rigidezza torsionale con ruota [Nm/rad]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion stiffness, fork alone [Nm/rad]</source>
        <translation>Rigidezza torsionale, sola forcella [Nm/rad]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion damping [Nms/rad]</source>
        <translation>Smorzamento torsionale [Nms/rad]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending arm h_W [m]</source>
        <translation>Braccio flessionale h_W [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending stiffness [Nm/rad]</source>
        <translation>Rigidezza flessionale [Nm/rad]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending inertia with wheel [kgm²]</source>
        <translation>Inerzia flessionale con ruota [kgm²]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bending damping [Nms/rad]</source>
        <translation>Smorzamento flessionale [Nms/rad]</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>with the wheel (eq. 58)</source>
        <translation>con la ruota (eq. 58)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fork alone (eq. 59)</source>
        <translation>sola forcella (eq. 59)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>h_W = %1 m, k = %2 Nm/rad</source>
        <translation>h_W = %1 m, k = %2 Nm/rad</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>No specimen to keep the model for.</source>
        <translation>Nessun provino per cui conservare il modello.</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+7"/>
        <source>Could not keep the model: %1</source>
        <translation>Impossibile conservare il modello: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Kept as model %1 of %2.</source>
        <translation>Conservato come modello %1 di %2.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Lumped fork models 1 to 3</source>
        <translation>Modelli di forcella a parametri concentrati da 1 a 3</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Bicycle fork stiffness and damping</source>
        <translation>Rigidezza e smorzamento della forcella da bicicletta</translation>
    </message>
</context>
<context>
    <name>mozzi::views::MeshEditor</name>
    <message>
        <location filename="../views/editors/mesh_table_model.cpp" line="+22"/>
        <source>cartesian</source>
        <translation>cartesiano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cylindrical</source>
        <translation>cilindrico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>spherical</source>
        <translation>sferico</translation>
    </message>
    <message>
        <location filename="../views/editors/mesh_editor.cpp" line="+67"/>
        <source>Cannot apply the edit: %1</source>
        <translation>Impossibile applicare la modifica: %1</translation>
    </message>
    <message>
        <location filename="../views/editors/mesh_table_model.cpp" line="+42"/>
        <source>Coordinates in the node&apos;s definition system; in a cylindrical system r [mm], theta [deg], z [mm], in a spherical one r [mm], theta [deg], phi [deg]</source>
        <translation>Coordinate nel sistema di definizione del nodo; in un sistema cilindrico r [mm], theta [gradi], z [mm], in uno sferico r [mm], theta [gradi], phi [gradi]</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Node</source>
        <translation>Nodo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>X [mm]</source>
        <translation>X [mm]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Y [mm]</source>
        <translation>Y [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z [mm]</source>
        <translation>Z [mm]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Def. CS</source>
        <translation>SC def.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Disp. CS</source>
        <translation>SC vis.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured DOFs</source>
        <translation>GDL misurati</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>Node A</source>
        <translation>Nodo A</translation>
    </message>
    <message>
        <location line="-2"/>
        <location line="+2"/>
        <source>Node B</source>
        <translation>Nodo B</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Node C</source>
        <translation>Nodo C</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node D</source>
        <translation>Nodo D</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CS</source>
        <translation>SC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Origin X [mm]</source>
        <translation>Origine X [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Origin Y [mm]</source>
        <translation>Origine Y [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Origin Z [mm]</source>
        <translation>Origine Z [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axes x | y | z</source>
        <translation>Assi x | y | z</translation>
    </message>
    <message>
        <location filename="../views/editors/mesh_editor.cpp" line="+104"/>
        <source>Import a mesh</source>
        <translation>Importa una mesh</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meshes (*.uff *.unv *.csv);;All files (*)</source>
        <translation>Mesh (*.uff *.unv *.csv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export the mesh</source>
        <translation>Esporta la mesh</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Universal file (*.uff);;Mesh CSV (*.csv)</source>
        <translation>File Universal (*.uff);;CSV della mesh (*.csv)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Undo %1</source>
        <translation>Annulla %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Redo %1</source>
        <translation>Ripeti %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Select one node to renumber.</source>
        <translation>Seleziona un nodo da rinumerare.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Renumber node</source>
        <translation>Rinumera nodo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New number of node %1:</source>
        <translation>Nuovo numero del nodo %1:</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Cannot place the mesh: %1</source>
        <translation>Impossibile posizionare la mesh: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 nodes, %2 lines, %3 faces, %4 coordinate systems, %5 measurement DOFs, %6 slave rules</source>
        <translation>%1 nodi, %2 linee, %3 facce, %4 sistemi di coordinate, %5 GDL di misura, %6 regole di dipendenza</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>This edit takes away nodes that measured data refers to:

%1

The data stays in the project but can no longer be drawn on this mesh. Go ahead?</source>
        <translation>Questa modifica elimina nodi a cui fanno riferimento dati misurati:

%1

I dati restano nel progetto ma non possono più essere disegnati su questa mesh. Procedere?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Measured data on these nodes</source>
        <translation>Dati misurati su questi nodi</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+6"/>
        <source>Cannot edit the mesh: %1</source>
        <translation>Impossibile modificare la mesh: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Edit cancelled: measured data refers to these nodes.</source>
        <translation>Modifica annullata: dati misurati fanno riferimento a questi nodi.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Select one coordinate system to delete.</source>
        <translation>Seleziona un sistema di coordinate da eliminare.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Select the nodes to delete.</source>
        <translation>Seleziona i nodi da eliminare.</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Select two or more nodes: lines join them in the order selected.</source>
        <translation>Seleziona due o più nodi: le linee li uniscono nell&apos;ordine di selezione.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Select three or four nodes, counter-clockwise, for a face.</source>
        <translation>Seleziona tre o quattro nodi, in senso antiorario, per una faccia.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot set the DOFs: %1</source>
        <translation>Impossibile impostare i GDL: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot read the rule: %1</source>
        <translation>Impossibile leggere la regola: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Select a rule to remove.</source>
        <translation>Seleziona una regola da rimuovere.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot build the template: %1</source>
        <translation>Impossibile costruire il template: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No template named %1.</source>
        <translation>Nessun template di nome %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+7"/>
        <location line="+10"/>
        <source>Cannot import %1: %2</source>
        <translation>Impossibile importare %1: %2</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>%1 holds no nodes (datasets 15 or 2411).</source>
        <translation>%1 non contiene nodi (dataset 15 o 2411).</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+10"/>
        <source>Cannot export: %1</source>
        <translation>Impossibile esportare: %1</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Mesh written to %1.</source>
        <translation>Mesh scritta in %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Mesh written to %1 (datasets 164, 2420, 2411, 82).</source>
        <translation>Mesh scritta in %1 (dataset 164, 2420, 2411, 82).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Faces, measurement DOFs and slave rules have no dataset there; export to CSV to keep them.</source>
        <translation>Facce, GDL di misura e regole di dipendenza non hanno un dataset in quel formato; esporta in CSV per conservarli.</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>Start from template</source>
        <translation>Parti da un template</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Replace the mesh by a template of the component (undoable)</source>
        <translation>Sostituisce la mesh con un template del componente (annullabile)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import…</source>
        <translation>Importa…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read a mesh from a universal file (15/2411, 18/2420, 82) or a mesh CSV</source>
        <translation>Legge una mesh da un file Universal (15/2411, 18/2420, 82) o da un CSV della mesh</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export…</source>
        <translation>Esporta…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the mesh as a universal file or a mesh CSV</source>
        <translation>Scrive la mesh come file Universal o come CSV della mesh</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Undo</source>
        <translation>Annulla</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Redo</source>
        <translation>Ripeti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add node</source>
        <translation>Aggiungi nodo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>Elimina</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delete the selected nodes (with their lines, faces and DOFs), lines, faces or coordinate system (Del)</source>
        <translation>Elimina i nodi selezionati (con le loro linee, facce e GDL), le linee, le facce o il sistema di coordinate (Del)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Renumber…</source>
        <translation>Rinumera…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Renumber all</source>
        <translation>Rinumera tutti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Number the nodes 1, 2, 3, … in table order</source>
        <translation>Numera i nodi 1, 2, 3, … nell&apos;ordine della tabella</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Snap to grid</source>
        <translation>Aggancia alla griglia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Round the selected nodes&apos; coordinates (all nodes when none is selected) to the grid</source>
        <translation>Arrotonda alla griglia le coordinate dei nodi selezionati (di tutti i nodi se nessuno è selezionato)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Grid spacing</source>
        <translation>Passo della griglia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add lines</source>
        <translation>Aggiungi linee</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Join the selected nodes by trace lines in the order they were picked</source>
        <translation>Unisce i nodi selezionati con linee di traccia nell&apos;ordine in cui sono stati scelti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add face</source>
        <translation>Aggiungi faccia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add CS</source>
        <translation>Aggiungi SC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add a cartesian coordinate system at the origin</source>
        <translation>Aggiunge un sistema di coordinate cartesiano nell&apos;origine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Labels</source>
        <translation>Etichette</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit view</source>
        <translation>Adatta vista</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the whole mesh</source>
        <translation>Mostra l&apos;intera mesh</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nodes</source>
        <translation>Nodi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lines</source>
        <translation>Linee</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Faces</source>
        <translation>Facce</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Coordinate systems</source>
        <translation>Sistemi di coordinate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slaved DOFs</source>
        <translation>GDL dipendenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>e.g. 5:+Z = 0.5 4:+Z + 0.5 6:+Z</source>
        <translation>ad es. 5:+Z = 0.5 4:+Z + 0.5 6:+Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set rule</source>
        <translation>Imposta regola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove rule</source>
        <translation>Rimuovi regola</translation>
    </message>
</context>
<context>
    <name>mozzi::views::MeshEditorPage</name>
    <message>
        <location filename="../views/editors/mesh_editor_page.cpp" line="+37"/>
        <source>hits of campaign &apos;%1&apos;</source>
        <translation>colpi della campagna &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>FRF set %1 &apos;%2&apos;</source>
        <translation>insieme di FRF %1 &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>modal result %1 &apos;%2&apos;</source>
        <translation>risultato modale %1 &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot read the mesh: %1</source>
        <translation>Impossibile leggere la mesh: %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Cannot save the mesh: %1</source>
        <translation>Impossibile salvare la mesh: %1</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ModeAnimationPage</name>
    <message>
        <location filename="../views/scene/mode_animation_page.cpp" line="+36"/>
        <source>The project has no modal results to animate.</source>
        <translation>Il progetto non ha risultati modali da animare.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot read the mesh: %1</source>
        <translation>Impossibile leggere la mesh: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1, mode %2</source>
        <translation>%1, modo %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>FRF set %1</source>
        <translation>Insieme di FRF %1</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ModeAnimationView</name>
    <message>
        <location filename="../views/scene/mode_animation_view.cpp" line="+256"/>
        <source>Export a frame</source>
        <translation>Esporta un fotogramma</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PNG image (*.png)</source>
        <translation>Immagine PNG (*.png)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export the animation</source>
        <translation>Esporta l&apos;animazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Animated GIF (*.gif);;PNG sequence (*.png)</source>
        <translation>GIF animata (*.gif);;Sequenza PNG (*.png)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Cannot place the mesh: %1</source>
        <translation>Impossibile posizionare la mesh: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>(none)</source>
        <translation>(nessuna)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2 Hz)</source>
        <translation>%1 (%2 Hz)</translation>
    </message>
    <message>
        <location line="+62"/>
        <location line="+5"/>
        <location line="+5"/>
        <source>Cannot show %1: %2</source>
        <translation>Impossibile mostrare %1: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot show %1: the mesh and the shape differ in node count</source>
        <translation>Impossibile mostrare %1: la mesh e la forma hanno un numero di nodi diverso</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>peak |u|</source>
        <translation>|u| di picco</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>No shape %1.</source>
        <translation>Nessuna forma %1.</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>No MAC: %1</source>
        <translation>Nessun MAC: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Open an FRF set to see operating deflection shapes.</source>
        <translation>Apri un insieme di FRF per vedere le forme operative di deflessione (ODS).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No ODS: %1</source>
        <translation>Nessuna ODS: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ODS at %1 Hz, driven at %2 (%3)</source>
        <translation>ODS a %1 Hz, forzata in %2 (%3)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Mozzi axis, pitch %1 m/rad</source>
        <translation>Asse di Mozzi, passo %1 m/rad</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>MAC %1 (%2 shared DOFs)</source>
        <translation>MAC %1 (%2 GDL in comune)</translation>
    </message>
    <message>
        <location line="+103"/>
        <location line="+33"/>
        <source>Cannot write %1.</source>
        <translation>Impossibile scrivere %1.</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>Frame written to %1.</source>
        <translation>Fotogramma scritto in %1.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Choose a shape to export.</source>
        <translation>Scegli una forma da esportare.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The frame rate must be 1 to 100 frames per second.</source>
        <translation>La frequenza dei fotogrammi deve essere da 1 a 100 fotogrammi al secondo.</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n frame(s) written.</source>
        <translation>
            <numerusform>%n fotogramma scritto.</numerusform>
            <numerusform>%n fotogrammi scritti.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>: %1 Hz</source>
        <translation>: %1 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, zeta %1 %</source>
        <translation>, zeta %1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 measured, %2 slaved, %3 interpolated, %4 still nodes</source>
        <translation>nodi: %1 misurati, %2 dipendenti, %3 interpolati, %4 fermi</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Mozzi (screw) axis: pitch %1 m/rad, direction (%2, %3, %4), through (%5, %6, %7) m</source>
        <translation>Asse di Mozzi (elicoidale): passo %1 m/rad, direzione (%2, %3, %4), passante per (%5, %6, %7) m</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>(low confidence: %1)</source>
        <translation>(bassa affidabilità: %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No Mozzi axis: %1</source>
        <translation>Nessun asse di Mozzi: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Choose a mode to animate.</source>
        <translation>Scegli un modo da animare.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Beside it</source>
        <translation>Accanto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ODS at</source>
        <translation>ODS a</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show</source>
        <translation>Mostra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Operating deflection shape of the FRF set at the line nearest this frequency</source>
        <translation>Forma operativa di deflessione dell&apos;insieme di FRF alla riga più vicina a questa frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click (or use the arrow keys) to animate the operating deflection shape at that frequency</source>
        <translation>Fare clic (o usare i tasti freccia) per animare la deformata operativa a quella frequenza</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sum of |H| [dB]</source>
        <translation>somma di |H| [dB]</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Amplitude</source>
        <translation>Ampiezza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0.1x to 10x the automatic amplitude (largest displacement 10 % of the mesh)</source>
        <translation>da 0,1x a 10x l&apos;ampiezza automatica (spostamento massimo pari al 10 % della mesh)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycles/s</source>
        <translation>Cicli/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Colour by displacement</source>
        <translation>Colori per spostamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Undeformed overlay</source>
        <translation>Sovrapponi l&apos;indeformata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arrows at measured nodes</source>
        <translation>Frecce sui nodi misurati</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mozzi (screw) axis</source>
        <translation>Asse di Mozzi (asse di moto elicoidale)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The screw axis of the rigid motion fitted to the shape&apos;s measured translations, with its pitch (thesis §1.5)</source>
        <translation>L&apos;asse elicoidale del moto rigido adattato alle traslazioni misurate della forma, con il suo passo (tesi §1.5)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause (Space)</source>
        <translation>Pausa (Space)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Play (Space)</source>
        <translation>Riproduci (Space)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export frame…</source>
        <translation>Esporta fotogramma…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export animation…</source>
        <translation>Esporta animazione…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One cycle as an animated GIF or numbered PNG files (25 frames/s)</source>
        <translation>Un ciclo come GIF animata o file PNG numerati (25 fotogrammi/s)</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ModelTestView</name>
    <message>
        <location filename="../views/gap/model_test_view.cpp" line="+266"/>
        <source>Export Diagnosis Report</source>
        <translation>Esporta rapporto di diagnosi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HTML report (*.html)</source>
        <translation>Rapporto HTML (*.html)</translation>
    </message>
    <message>
        <location line="+89"/>
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
        <location line="+25"/>
        <source>Diagnosis done.</source>
        <translation>Diagnosi completata.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The diagnosis stopped: %1</source>
        <translation>La diagnosi si è interrotta: %1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1 at %2 (equivalent at %3)</source>
        <translation>%1 in %2 (equivalente in %3)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 at %2 (and %3 equivalent locations)</source>
        <translation>%1 in %2 (e altre %3 posizioni equivalenti)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Verdict: %1</source>
        <translation>Verdetto: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Item</source>
        <translation>Elemento</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <location line="+0"/>
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
        <location line="+49"/>
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
        <location line="+11"/>
        <source>(not identifiable)</source>
        <translation>(non identificabile)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (+%2 equivalent)</source>
        <translation>%1 (+%2 equiv.)</translation>
    </message>
    <message>
        <location filename="../views/gap/model_test_view_kept.cpp" line="+250"/>
        <location line="+26"/>
        <source>model + %1 + %2</source>
        <translation>modello + %1 + %2</translation>
    </message>
    <message>
        <location line="-21"/>
        <location line="+26"/>
        <source>model + %1</source>
        <translation>modello + %1</translation>
    </message>
    <message>
        <location filename="../views/gap/model_test_view.cpp" line="+71"/>
        <location line="+89"/>
        <source>model + best effect</source>
        <translation>modello + effetto migliore</translation>
    </message>
    <message>
        <location line="-79"/>
        <source>Model vs test</source>
        <translation>Modello contro prova</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Model</source>
        <translation>Modello</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Test</source>
        <translation>Prova</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Ranked effects</source>
        <translation>Effetti in classifica</translation>
    </message>
    <message>
        <location line="-50"/>
        <source>Nothing to export: run the diagnosis first.</source>
        <translation>Niente da esportare: esegui prima la diagnosi.</translation>
    </message>
    <message>
        <location line="-626"/>
        <source>effect</source>
        <translation>effetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>nessuno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ambiguous</source>
        <translation>ambiguo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>partial</source>
        <translation>parziale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexplained</source>
        <translation>non spiegato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not identifiable</source>
        <translation>non identificabile</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure [bar]</source>
        <translation>Pressione [bar]</translation>
    </message>
    <message>
        <location line="+380"/>
        <location filename="../views/gap/model_test_view_kept.cpp" line="+11"/>
        <source>%1 and %2</source>
        <translation>%1 e %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 at %2</source>
        <translation>%1 in %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Verdict: %1 (%2)</source>
        <translation>Verdetto: %1 (%2)</translation>
    </message>
    <message>
        <location line="+216"/>
        <location line="+8"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Kept diagnoses</source>
        <translation>Diagnosi conservate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The gap diagnoses this project keeps</source>
        <translation>Le diagnosi del divario che questo progetto conserva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show</source>
        <translation>Mostra</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location filename="../views/gap/model_test_view_kept.cpp" line="-101"/>
        <source>Lowest frequency used (0 = from the first line)</source>
        <translation>Frequenza minima usata (0 = dalla prima riga)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest frequency used (0 = to the last line)</source>
        <translation>Frequenza massima usata (0 = fino all&apos;ultima riga)</translation>
    </message>
    <message>
        <location filename="../views/gap/model_test_view.cpp" line="+1"/>
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
        <location filename="../views/gap/model_test_view_kept.cpp" line="+11"/>
        <source>Candidate effects</source>
        <translation>Effetti candidati</translation>
    </message>
    <message>
        <location filename="../views/gap/model_test_view.cpp" line="+6"/>
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
        <location line="+18"/>
        <location filename="../views/gap/model_test_view_kept.cpp" line="-116"/>
        <source>No diagnosis yet</source>
        <translation>Nessuna diagnosi</translation>
    </message>
    <message>
        <location filename="../views/gap/model_test_view_kept.cpp" line="+21"/>
        <source>No project is open.</source>
        <translation>Nessun progetto aperto.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Analysis %1: %2</source>
        <translation>Analisi %1: %2</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>First line of the kept diagnosis shown; a new run on files uses the value here</source>
        <translation>Prima riga della diagnosi conservata mostrata; una nuova esecuzione sui file usa il valore qui</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last line of the kept diagnosis shown; a new run on files uses the value here</source>
        <translation>Ultima riga della diagnosi conservata mostrata; una nuova esecuzione sui file usa il valore qui</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The kept diagnosis shown has no frequency band; the band sets up the next run on files</source>
        <translation>La diagnosi conservata mostrata non ha una banda di frequenza; la banda imposta la prossima esecuzione sui file</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Candidate effects of the kept diagnosis</source>
        <translation>Effetti candidati della diagnosi conservata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The effects the kept diagnosis ranked; a run on files lists those its data offer</source>
        <translation>Gli effetti classificati dalla diagnosi conservata; un&apos;esecuzione sui file elenca quelli offerti dai suoi dati</translation>
    </message>
    <message numerus="yes">
        <location line="+30"/>
        <source>and %n more</source>
        <translation>
            <numerusform>e %n altra</numerusform>
            <numerusform>e altre %n</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Locations:</source>
        <translation>Posizioni:</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Kept diagnosis &quot;%1&quot; (analysis %2), as stored.</source>
        <translation>Diagnosi conservata &quot;%1&quot; (analisi %2), così come è stata salvata.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>With %1 the held-out residual is %2% lower.</source>
        <translation>Con %1 il residuo sui dati esclusi dal fit è più basso del %2%.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> and </source>
        <translation> e </translation>
    </message>
</context>
<context>
    <name>mozzi::views::PageTabs</name>
    <message>
        <location filename="../views/common/page_tabs.cpp" line="+191"/>
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
        <location filename="../views/panels/parameter_form.cpp" line="+252"/>
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
        <location filename="../views/panels/project_overview.cpp" line="+258"/>
        <source>needs a record this project does not hold yet</source>
        <translation>richiede un dato che questo progetto non contiene ancora</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>opens on its own (Pages or Tools menu)</source>
        <translation>si apre da sola (menu Pagine o Strumenti)</translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%1: mesh of %n nodes</source>
        <translation>
            <numerusform>%1: mesh di %n nodo</numerusform>
            <numerusform>%1: mesh di %n nodi</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Setting up a specimen</source>
        <translation>Preparazione di un provino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>At the rig</source>
        <translation>Al banco</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reviewing results</source>
        <translation>Analisi dei risultati</translation>
    </message>
    <message>
        <location line="+70"/>
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
        <source>Mesh nodes</source>
        <translation>Nodi della mesh</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Campaigns</source>
        <translation>Campagne</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FRF sets</source>
        <translation>Insiemi di FRF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modal results</source>
        <translation>Risultati modali</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rig tests</source>
        <translation>Prove al banco</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Tyre tests</source>
        <translation>Prove sugli pneumatici</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Analyses</source>
        <translation>Analisi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation>Descrizione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Page</source>
        <translation>Pagina</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>What it shows</source>
        <translation>Cosa mostra</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Opens on</source>
        <translation>Si apre su</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start here: double-click a page to open it on this project&apos;s data</source>
        <translation>Da dove iniziare: doppio clic su una pagina per aprirla sui dati di questo progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Open Page</source>
        <translation>&amp;Apri pagina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To leave with a document: File &gt; Export &gt; Report...</source>
        <translation>Per uscire con un documento: File &gt; Esporta &gt; Relazione...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specimens and what each holds</source>
        <translation>Provini e cosa contiene ciascuno</translation>
    </message>
    <message>
        <location line="+7"/>
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
        <location filename="../views/common/project_tree.cpp" line="+32"/>
        <source>stability sweep</source>
        <translation>analisi di stabilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wheelchair manoeuvre</source>
        <translation>manovra della carrozzina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gap diagnosis</source>
        <translation>diagnosi del divario</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Stability sweeps</source>
        <translation>Analisi di stabilità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wheelchair manoeuvres</source>
        <translation>Manovre della carrozzina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gap diagnoses</source>
        <translation>Diagnosi del divario</translation>
    </message>
    <message>
        <location line="+147"/>
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
        <location line="+21"/>
        <location line="+26"/>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <location line="-74"/>
        <location line="+5"/>
        <location line="+43"/>
        <location line="+26"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="-74"/>
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
        <location line="+7"/>
        <source>running</source>
        <translation>in corso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>complete</source>
        <translation>completata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted</source>
        <translation>interrotta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>non riuscita</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Specimen</source>
        <translation>Provino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>Stato</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Recorded (UTC)</source>
        <translation>Registrata (UTC)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steps recorded</source>
        <translation>Passi registrati</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Results</source>
        <translation>Risultati</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rig tests</source>
        <translation>Prove al banco</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tyre tests</source>
        <translation>Prove pneumatici</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Analyses</source>
        <translation>Analisi</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Analysis id</source>
        <translation>Id dell&apos;analisi</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Data</source>
        <translation>Dati</translation>
    </message>
</context>
<context>
    <name>mozzi::views::RelaxationPage</name>
    <message>
        <location filename="../views/tyre/relaxation_page.cpp" line="+186"/>
        <source>The project holds no tyre specimen.</source>
        <translation>Il progetto non contiene alcun pneumatico.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reading the relaxation tests and predicting (thesis eq. 48)...</source>
        <translation>Lettura delle prove di rilassamento e previsione (eq. 48 della tesi)...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tyre relaxation</source>
        <translation>Rilassamento pneumatico</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot show the relaxation length: %1</source>
        <translation>Impossibile mostrare la lunghezza di rilassamento: %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>No relaxation test of this tyre in the project: the prediction alone.</source>
        <translation>Nessuna prova di rilassamento di questo pneumatico nel progetto: solo la previsione.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n relaxation test(s) of tyre %1.</source>
        <translation>
            <numerusform>%n prova di rilassamento del pneumatico %1.</numerusform>
            <numerusform>%n prove di rilassamento del pneumatico %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n relaxation test(s) hold no result and are not drawn.</source>
        <translation>
            <numerusform>%n prova di rilassamento non ha risultati e non è disegnata.</numerusform>
            <numerusform>%n prove di rilassamento non hanno risultati e non sono disegnate.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 bar: measured %2 m, predicted %3 m (%4%).</source>
        <translation>%1 bar: misurata %2 m, prevista %3 m (%4%).</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>Inputs of eq. 48: ring stiffness from thesis Table 16 (nominal pressure); contact half-length a from Table 17 for the bars and as each test stored it for the lines; F_z %1 N; cornering stiffness from the project&apos;s steady-state test at %n of the 7 Table 17 pressures, elsewhere assumed %2 F_z; friction %3 and slip angle 1.5° assumed (§5.4). Tyre mass %4 kg and damping ratio %5 assumed (eq. 45 to 47).</source>
        <translation>
            <numerusform>Dati dell&apos;eq. 48: rigidezze dell&apos;anello dalla Tabella 16 della tesi (pressione nominale); semilunghezza dell&apos;impronta a dalla Tabella 17 per le barre e come memorizzata da ciascuna prova per le linee; F_z %1 N; rigidezza di deriva dalla prova stazionaria del progetto a %n delle 7 pressioni della Tabella 17, altrove assunta %2 F_z; attrito %3 e angolo di deriva 1,5° assunti (§5.4). Massa del pneumatico %4 kg e rapporto di smorzamento %5 assunti (eq. da 45 a 47).</numerusform>
            <numerusform>Dati dell&apos;eq. 48: rigidezze dell&apos;anello dalla Tabella 16 della tesi (pressione nominale); semilunghezza dell&apos;impronta a dalla Tabella 17 per le barre e come memorizzata da ciascuna prova per le linee; F_z %1 N; rigidezza di deriva dalla prova stazionaria del progetto a %n delle 7 pressioni della Tabella 17, altrove assunta %2 F_z; attrito %3 e angolo di deriva 1,5° assunti (§5.4). Massa del pneumatico %4 kg e rapporto di smorzamento %5 assunti (eq. da 45 a 47).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+32"/>
        <source>measured, %1 bar</source>
        <translation>misurata, %1 bar</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>standard error</source>
        <translation>errore standard</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>predicted (eq. 48), %1 bar</source>
        <translation>prevista (eq. 48), %1 bar</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>predicted (eq. 48)</source>
        <translation>prevista (eq. 48)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>contact patch a m</source>
        <translation>impronta a m</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>camber mode</source>
        <translation>modo di camber</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lateral mode</source>
        <translation>modo laterale</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>C-shaped mode</source>
        <translation>modo a C</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S-shaped mode</source>
        <translation>modo a S</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>modes k ≥ 4</source>
        <translation>modi k ≥ 4</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>measured (band mean)</source>
        <translation>misurata (media nella banda)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Could not keep the prediction: %1</source>
        <translation>Impossibile conservare la previsione: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Relaxation prediction of %1 kept in the project (analysis %2)</source>
        <translation>Previsione del rilassamento di %1 conservata nel progetto (analisi %2)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Tyre:</source>
        <translation>Pneumatico:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep in project</source>
        <translation>Conserva nel progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Store the prediction and its inputs as an analysis of the project</source>
        <translation>Memorizza la previsione e i suoi dati come analisi del progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relaxation length against yaw frequency</source>
        <translation>Lunghezza di rilassamento in funzione della frequenza di imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+3"/>
        <source>σ [m]</source>
        <translation>σ [m]</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Relaxation length against pressure (thesis Figure 43)</source>
        <translation>Lunghezza di rilassamento in funzione della pressione (Figura 43 della tesi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inflation pressure [bar]</source>
        <translation>Pressione di gonfiaggio [bar]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rigid-ring modes (thesis Table 16, eq. 45 to 47)</source>
        <translation>Modi ad anello rigido (Tabella 16 della tesi, eq. da 45 a 47)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>k</source>
        <translation>k</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mode</source>
        <translation>modo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f [Hz]</source>
        <translation>f [Hz]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ζ</source>
        <translation>ζ</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>m_k [kg]</source>
        <translation>m_k [kg]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>C_k [kN/m]</source>
        <translation>C_k [kN/m]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>c_k [N s/m]</source>
        <translation>c_k [N s/m]</translation>
    </message>
</context>
<context>
    <name>mozzi::views::ReportDialog</name>
    <message>
        <location filename="../views/report/report_dialog.cpp" line="+55"/>
        <source>Report PDF</source>
        <translation>PDF della relazione</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PDF documents (*.pdf)</source>
        <translation>Documenti PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Report HTML folder</source>
        <translation>Cartella HTML della relazione</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The project&apos;s report template cannot be read: %1</source>
        <translation>Impossibile leggere il modello di relazione del progetto: %1</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>The report template was not saved: %1</source>
        <translation>Il modello di relazione non è stato salvato: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Report</source>
        <translation>Relazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sections (each is left out when the project has no data for it):</source>
        <translation>Sezioni (ognuna è omessa quando il progetto non ha dati per essa):</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Specimen:</source>
        <translation>Provino:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every specimen</source>
        <translation>Tutti i provini</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Report language:</source>
        <translation>Lingua della relazione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF</source>
        <translation>PDF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HTML folder</source>
        <translation>Cartella HTML</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
</context>
<context>
    <name>mozzi::views::RigTestPage</name>
    <message>
        <location filename="../views/rigs/rig_test_page.cpp" line="+256"/>
        <source>Stiffness rig (simulated Motostiffmeter)</source>
        <translation>Banco di rigidezza (Motostiffmeter simulato)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tyre tester (simulated Mototiremeter)</source>
        <translation>Banco prova pneumatici (Mototiremeter simulato)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Specimen</source>
        <translation>Provino</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Tyre</source>
        <translation>Pneumatico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test</source>
        <translation>Prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated rig</source>
        <translation>Banco simulato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test settings</source>
        <translation>Impostazioni della prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set-up: plate, lasers, load point (mm)</source>
        <translation>Allestimento: piastra, laser, punto di carico (mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measurement</source>
        <translation>Misura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set-up view</source>
        <translation>Vista dell&apos;allestimento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set-up over the specimen</source>
        <translation>Allestimento sul provino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>u [m] (plate plane)</source>
        <translation>u [m] (piano della piastra)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>v [m]</source>
        <translation>v [m]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Result stored in the project</source>
        <translation>Risultato memorizzato nel progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run (F5)</source>
        <translation>Esegui (F5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Check the settings against the machine&apos;s limits and run the test</source>
        <translation>Verifica le impostazioni rispetto ai limiti della macchina ed esegue la prova</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop (Esc)</source>
        <translation>Arresta (Esc)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the test: the finished steps stay in the project</source>
        <translation>Arresta la prova: i passi completati restano nel progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step</source>
        <translation>Passo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Quantity</source>
        <translation>Grandezza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std. uncertainty</source>
        <translation>Incertezza tipo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Unità</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ready. Pick a test and press Run.</source>
        <translation>Pronto. Scegli una prova e premi Esegui.</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Static ramp</source>
        <translation>Rampa statica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A slow force ramp: k_lat, the twist axis, a_tw and k_tw</source>
        <translation>Una rampa di forza lenta: k_lat, l&apos;asse di torsione, a_tw e k_tw</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sine sweep</source>
        <translation>Scansione sinusoidale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A sine per frequency: the dynamic twist axis and stiffness</source>
        <translation>Una sinusoide per frequenza: asse di torsione e rigidezza dinamici</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Harmonic yaw</source>
        <translation>Imbardata armonica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw oscillations at a list of frequencies: the relaxation length</source>
        <translation>Oscillazioni d&apos;imbardata a una serie di frequenze: la lunghezza di rilassamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Steady-state sweeps</source>
        <translation>Scansioni stazionarie</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side-slip and camber sweeps: the characteristics and the Magic Formula</source>
        <translation>Scansioni di deriva e di campanatura: le caratteristiche e la Magic Formula</translation>
    </message>
    <message numerus="yes">
        <location filename="../views/rigs/rig_test_setup.cpp" line="-46"/>
        <source>Plate (u, v) [mm]: %n laser(s) at %1; load point at (%2, %3); the other end locked.</source>
        <translation>
            <numerusform>Piastra (u, v) [mm]: %n laser in %1; punto di carico in (%2, %3); l&apos;altra estremità bloccata.</numerusform>
            <numerusform>Piastra (u, v) [mm]: %n laser in %1; punto di carico in (%2, %3); l&apos;altra estremità bloccata.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Load F_z %1 N; contact half-length a %2 mm (Table 17); working limits side-slip ±%3°, camber ±%4° (machine ±%5°, ±%6°, disk up to %7 km/h).</source>
        <translation>Carico F_z %1 N; semilunghezza di contatto a %2 mm (Tabella 17); limiti di lavoro deriva ±%3°, campanatura ±%4° (macchina ±%5°, ±%6°, disco fino a %7 km/h).</translation>
    </message>
    <message>
        <location line="+72"/>
        <location line="+2"/>
        <source>No outline drawn: %1</source>
        <translation>Nessun contorno disegnato: %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Set-up not valid, field &apos;%1&apos;: %2</source>
        <translation>Allestimento non valido, campo &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set-up not valid: %1</source>
        <translation>Allestimento non valido: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Outline: %1, approximate (not to scale of a drawing).</source>
        <translation>Contorno: %1, approssimato (non in scala di un disegno).</translation>
    </message>
    <message>
        <location filename="../views/rigs/rig_test_plots.cpp" line="+146"/>
        <source>Time [s]</source>
        <translation>Tempo [s]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Load cell and load-point displacement</source>
        <translation>Cella di carico e spostamento del punto di carico</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+6"/>
        <source>Force [N]</source>
        <translation>Forza [N]</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Displacement [mm]</source>
        <translation>Spostamento [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>load cell [N]</source>
        <translation>cella di carico [N]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>load-point displacement [mm]</source>
        <translation>spostamento del punto di carico [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Force vs load-point displacement</source>
        <translation>Forza in funzione dello spostamento del punto di carico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load-point displacement [mm]</source>
        <translation>Spostamento del punto di carico [mm]</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+29"/>
        <source>current frequency</source>
        <translation>frequenza corrente</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>measured</source>
        <translation>misura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>F = k_lat x (stored k_lat)</source>
        <translation>F = k_lat x (k_lat memorizzata)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sine fit, last frequency</source>
        <translation>fit sinusoidale, ultima frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dynamic twist axis against frequency</source>
        <translation>Asse di torsione dinamico in funzione della frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination [deg]</source>
        <translation>Inclinazione [°]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Twist arm a_tw [mm]</source>
        <translation>Braccio di torsione a_tw [mm]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclination ± 1σ</source>
        <translation>inclinazione ± 1σ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a_tw ± 1σ</source>
        <translation>a_tw ± 1σ</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Lateral force and aligning moment</source>
        <translation>Forza laterale e momento di autoallineamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <location line="+2"/>
        <source>F_y [N]</source>
        <translation>F_y [N]</translation>
    </message>
    <message>
        <location line="-3"/>
        <location line="+2"/>
        <source>M_z [N m]</source>
        <translation>M_z [N m]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Steady-state characteristic</source>
        <translation>Caratteristica stazionaria</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Side-slip, camber [deg]</source>
        <translation>Deriva, campanatura [gradi]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>F_y vs side-slip</source>
        <translation>F_y in funzione della deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>F_y vs camber</source>
        <translation>F_y in funzione della campanatura</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cornering stiffness (stored)</source>
        <translation>rigidezza di deriva (memorizzata)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>camber stiffness (stored)</source>
        <translation>rigidezza di campanatura (memorizzata)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magic Formula vs side-slip</source>
        <translation>Magic Formula in funzione della deriva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magic Formula vs camber</source>
        <translation>Magic Formula in funzione della campanatura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lateral force vs yaw angle</source>
        <translation>Forza laterale in funzione dell&apos;angolo d&apos;imbardata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw angle [deg]</source>
        <translation>Angolo d&apos;imbardata [gradi]</translation>
    </message>
    <message>
        <location filename="../views/rigs/rig_test_run.cpp" line="+71"/>
        <source>Open or create a project first: the test is stored in it.</source>
        <translation>Apri o crea prima un progetto: la prova viene memorizzata lì.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The project is open read-only (%1): the test could not be stored.</source>
        <translation>Il progetto è aperto in sola lettura (%1): impossibile memorizzare la prova.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Correct the settings marked in the form first.</source>
        <translation>Correggi prima le impostazioni segnalate nel modulo.</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+23"/>
        <source>Not started: %1</source>
        <translation>Non avviata: %1</translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+23"/>
        <source>Rig test not started: %1</source>
        <translation>Prova al banco non avviata: %1</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>Running: %1 on %2</source>
        <translation>In corso: %1 su %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rig test started: %1 on %2</source>
        <translation>Prova al banco avviata: %1 su %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 on %2</source>
        <translation>%1 su %2</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Complete: stored as &apos;%1&apos;.</source>
        <translation>Completata: memorizzata come &apos;%1&apos;.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Interrupted: stored as &apos;%1&apos; with the finished steps (%2).</source>
        <translation>Interrotta: memorizzata come &apos;%1&apos; con i passi completati (%2).</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>Failed: %1</source>
        <translation>Non riuscita: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Stopping: the sequence keeps the finished steps...</source>
        <translation>Arresto in corso: la sequenza conserva i passi completati...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Rig test: %1</source>
        <translation>Prova al banco: %1</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>%1 at %2 s</source>
        <translation>%1 a %2 s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>load point %1 mm</source>
        <translation>punto di carico %1 mm</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Step %1 (%2) committed.</source>
        <translation>Passo %1 (%2) salvato.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step %1 (%2) kept without a result: %3</source>
        <translation>Passo %1 (%2) conservato senza risultato: %3</translation>
    </message>
    <message>
        <location filename="../views/rigs/rig_test_plots.cpp" line="+131"/>
        <source>Cannot read the rig test: %1</source>
        <translation>Impossibile leggere la prova al banco: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot read the tyre test: %1</source>
        <translation>Impossibile leggere la prova dello pneumatico: %1</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>whole test</source>
        <translation>intera prova</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>running</source>
        <translation>in corso</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>complete</source>
        <translation>completata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted</source>
        <translation>interrotta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>non riuscita</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; (%2)</source>
        <translation>&apos;%1&apos; (%2)</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>… %n more in the table</source>
        <translation>
            <numerusform>… %n altra nella tabella</numerusform>
            <numerusform>… altre %n nella tabella</numerusform>
        </translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Cannot read the rig test&apos;s twist axes: %1</source>
        <translation>Impossibile leggere gli assi di torsione della prova: %1</translation>
    </message>
</context>
<context>
    <name>mozzi::views::SceneView</name>
    <message>
        <location filename="../views/scene/scene_view.cpp" line="+626"/>
        <source>peak |u|</source>
        <translation>|u| di picco</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot show the mesh: %1</source>
        <translation>Impossibile mostrare la mesh: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot place the mesh: %1</source>
        <translation>Impossibile posizionare la mesh: %1</translation>
    </message>
</context>
<context>
    <name>mozzi::views::StabilityPage</name>
    <message>
        <location filename="../views/stability/stability_page.cpp" line="+291"/>
        <source>Computing the eigenvalues against speed...</source>
        <translation>Calcolo degli autovalori in funzione della velocità...</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Stability against speed</source>
        <translation>Stabilità in funzione della velocità</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>Cannot compute: %1</source>
        <translation>Impossibile calcolare: %1</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>%1 %2 at %3 m/s</source>
        <translation>%1 %2 a %3 m/s</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 %2 m/s</source>
        <translation>%1 %2 m/s</translation>
    </message>
    <message>
        <location line="-77"/>
        <source>No real part crosses zero in this speed range.</source>
        <translation>Nessuna parte reale attraversa lo zero in questo intervallo di velocità.</translation>
    </message>
    <message>
        <location line="-226"/>
        <source>built-in (Sharp 1971 standard machine)</source>
        <translation>integrati (macchina standard di Sharp 1971)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>built-in (benchmark bicycle, Meijaard et al. 2007)</source>
        <translation>incorporati (bicicletta di riferimento, Meijaard et al. 2007)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Vehicle parameter file</source>
        <translation>File dei parametri del veicolo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.csv);;All files (*)</source>
        <translation>File dei parametri (*.csv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>thesis (Table 12)</source>
        <translation>tesi (Tabella 12)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>thesis steel fork (§6.4, §6.5)</source>
        <translation>forcella in acciaio della tesi (§6.4, §6.5)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>kept: %1 (analysis %2)</source>
        <translation>conservata: %1 (analisi %2)</translation>
    </message>
    <message>
        <location line="+87"/>
        <location line="+2"/>
        <location line="+7"/>
        <source>Not kept: %1</source>
        <translation>Non conservato: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kept in the project as analysis %1.</source>
        <translation>Conservato nel progetto come analisi %1.</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>Critical speeds: %1</source>
        <translation>Velocità critiche: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rigid fork: no real part crosses zero.</source>
        <translation>Forcella rigida: nessuna parte reale attraversa lo zero.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rigid fork: %1</source>
        <translation>Forcella rigida: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stored: %1. %2</source>
        <translation>Conservato: %1. %2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 (rigid fork)</source>
        <translation>%1 (forcella rigida)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>rigid: %1</source>
        <translation>rigida: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Model:</source>
        <translation>Modello:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Benchmark bicycle (Meijaard et al. 2007)</source>
        <translation>Bicicletta di riferimento (Meijaard et al. 2007)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Benchmark bicycle, steel fork in bending (thesis §6.5)</source>
        <translation>Bicicletta di riferimento, forcella d&apos;acciaio flessibile (tesi §6.5)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Benchmark bicycle, steel fork in torsion (thesis §6.4)</source>
        <translation>Bicicletta di riferimento, forcella d&apos;acciaio torsionale (tesi §6.4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motorcycle (Sharp 1971), rigid fork</source>
        <translation>Motocicletta (Sharp 1971), forcella rigida</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motorcycle, lumped fork model 1 (thesis Table 12)</source>
        <translation>Motocicletta, modello a parametri concentrati 1 della forcella (Tabella 12 della tesi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motorcycle, lumped fork model 2 (thesis Table 12)</source>
        <translation>Motocicletta, modello a parametri concentrati 2 della forcella (Tabella 12 della tesi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Motorcycle, lumped fork model 3 (thesis Table 12)</source>
        <translation>Motocicletta, modello a parametri concentrati 3 della forcella (Tabella 12 della tesi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compare with the rigid fork</source>
        <translation>Confronta con la forcella rigida</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fork:</source>
        <translation>Forcella:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The thesis&apos;s fork, or one the project keeps (Lumped Fork page)</source>
        <translation>La forcella della tesi, o una conservata nel progetto (pagina Forcella a parametri concentrati)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sweep the same vehicle with a rigid fork too and draw it with open symbols</source>
        <translation>Calcola anche lo stesso veicolo con la forcella rigida e disegnalo con simboli vuoti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameters:</source>
        <translation>Parametri:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From file...</source>
        <translation>Da file...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A bicycle (Meijaard et al. 2007) or motorcycle (Sharp 1971) parameter file, as mozzi-cli stability --params reads</source>
        <translation>Un file di parametri di bicicletta (Meijaard et al. 2007) o di motocicletta (Sharp 1971), come lo legge mozzi-cli stability --params</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Built-in</source>
        <translation>Incorporati</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Speeds from, to, step:</source>
        <translation>Velocità da, a, passo:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compute</source>
        <translation>Calcola</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kept results:</source>
        <translation>Risultati conservati:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stability sweeps the project keeps (this page, mozzi-cli stability --project)</source>
        <translation>Analisi di stabilità al variare della velocità conservate nel progetto (questa pagina, mozzi-cli stability --project)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show</source>
        <translation>Mostra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Real part of the eigenvalues</source>
        <translation>Parte reale degli autovalori</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+3"/>
        <source>Speed [m/s]</source>
        <translation>Velocità [m/s]</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Re λ [1/s]</source>
        <translation>Re λ [1/s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Imaginary part (oscillating modes)</source>
        <translation>Parte immaginaria (modi oscillanti)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Im λ [rad/s]</source>
        <translation>Im λ [rad/s]</translation>
    </message>
</context>
<context>
    <name>mozzi::views::StabilizationPlot</name>
    <message>
        <location filename="../views/plots/stabilization_plot.cpp" line="+180"/>
        <source>Frequency [Hz]</source>
        <translation>Frequenza [Hz]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model order</source>
        <translation>Ordine del modello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>[dB]</source>
        <translation>[dB]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>new</source>
        <translation>nuovo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stable</source>
        <translation>stabile</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f stable</source>
        <translation>f stabile</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f, d stable</source>
        <translation>f, d stabili</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>f, v stable</source>
        <translation>f, v stabili</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>selected</source>
        <translation>selezionato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>backdrop</source>
        <translation>sfondo</translation>
    </message>
</context>
<context>
    <name>mozzi::views::StiffnessTablePage</name>
    <message>
        <location filename="../views/stiffness/stiffness_table_page.cpp" line="+66"/>
        <source>Thesis values beside the measured ones</source>
        <translation>Valori della tesi accanto a quelli misurati</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Where a specimen is one of the thesis&apos;s, its printed values (Tables 3 to 5, 7, 9, 10, 13) and the difference from the measured ones</source>
        <translation>Se il provino è uno di quelli della tesi, i suoi valori pubblicati (Tabelle da 3 a 5, 7, 9, 10, 13) e la differenza da quelli misurati</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Copy as CSV</source>
        <translation>Copia come CSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export CSV...</source>
        <translation>Esporta CSV...</translation>
    </message>
    <message>
        <location line="+58"/>
        <location line="+105"/>
        <source>measured</source>
        <translation>misurato</translation>
    </message>
    <message>
        <location line="-89"/>
        <source>%1 %2, one standard deviation %3 %2 (as stored)</source>
        <translation>%1 %2, deviazione standard %3 %2 (come memorizzato)</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+84"/>
        <source>thesis</source>
        <translation>tesi</translation>
    </message>
    <message>
        <location line="-68"/>
        <source>difference</source>
        <translation>differenza</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Thesis values as printed (misprinted units corrected, docs/validation/stiffness.md) from %1.</source>
        <translation>Valori della tesi come pubblicati (unità errate corrette, docs/validation/stiffness.md) da %1.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No project is open.</source>
        <translation>Nessun progetto aperto.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Could not read the rig tests: %1</source>
        <translation>Impossibile leggere le prove al banco: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The project holds no static stiffness test: run one on the Stiffness Rig page.</source>
        <translation>Il progetto non contiene prove statiche di rigidezza: eseguirne una nella pagina Banco di rigidezza.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n static test(s); sine sweeps are on the Twist Axes page.</source>
        <translation>
            <numerusform>%n prova statica; le scansioni sinusoidali sono nella pagina Assi di torsione.</numerusform>
            <numerusform>%n prove statiche; le scansioni sinusoidali sono nella pagina Assi di torsione.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not shown: %1</source>
        <translation>Non mostrato: %1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>quantity</source>
        <translation>grandezza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>unit</source>
        <translation>unità</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>standard deviation</source>
        <translation>deviazione standard</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+5"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Stiffness tables copied as CSV.</source>
        <translation>Tabelle di rigidezza copiate come CSV.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Export the stiffness tables</source>
        <translation>Esporta le tabelle di rigidezza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CSV data (*.csv)</source>
        <translation>Dati CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stiffness tables written to %1.</source>
        <translation>Tabelle di rigidezza scritte in %1.</translation>
    </message>
</context>
<context>
    <name>mozzi::views::TwistAxesPage</name>
    <message>
        <location filename="../views/scene/twist_axes_page.cpp" line="+269"/>
        <source>Specimen</source>
        <translation>Provino</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static test</source>
        <translation>Prova statica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dynamic test</source>
        <translation>Prova dinamica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency</source>
        <translation>Frequenza</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quantity</source>
        <translation>Grandezza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Static</source>
        <translation>Statica</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+490"/>
        <source>Dynamic</source>
        <translation>Dinamica</translation>
    </message>
    <message>
        <location line="-489"/>
        <source>u [m] (plate plane)</source>
        <translation>u [m] (piano della piastra)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>v [m]</source>
        <translation>v [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The static ramp test whose twist axis is drawn (black)</source>
        <translation>La prova a rampa statica il cui asse di torsione è disegnato (nero)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The sine sweep whose dynamic twist axis is drawn (red) at the slider&apos;s frequency</source>
        <translation>La scansione sinusoidale il cui asse di torsione dinamico è disegnato (rosso) alla frequenza del cursore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Excitation frequency of the sine sweep: moves the dynamic twist axis</source>
        <translation>Frequenza di eccitazione della scansione sinusoidale: sposta l&apos;asse di torsione dinamico</translation>
    </message>
    <message>
        <location line="+50"/>
        <location line="+1"/>
        <source>(none)</source>
        <translation>(nessuna)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 (imported)</source>
        <translation>%1 (importato)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Open a project to keep the imported tests in.</source>
        <translation>Apri un progetto in cui conservare le prove importate.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot add a specimen: %1</source>
        <translation>Impossibile aggiungere un provino: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot keep %1: %2</source>
        <translation>Impossibile conservare %1: %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Choose an imported static or dynamic test to keep.</source>
        <translation>Scegli una prova statica o dinamica importata da conservare.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Kept in the project: %1</source>
        <translation>Conservate nel progetto: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Cannot read the rig test: %1</source>
        <translation>Impossibile leggere la prova al banco: %1</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Cannot read &apos;%1&apos;: %2</source>
        <translation>Impossibile leggere &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>No dynamic axis to trace: %1</source>
        <translation>Nessun asse dinamico da tracciare: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the test does not name a virtual specimen, so no outline is known</source>
        <translation>la prova non indica un provino virtuale, quindi nessuna sagoma è nota</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>No stiffness-rig test to show: run one on the Stiffness Rig page.</source>
        <translation>Nessuna prova al banco di rigidezza da mostrare: eseguirne una nella pagina Banco di rigidezza.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No project is open.</source>
        <translation>Nessun progetto aperto.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; is %2: %3</source>
        <translation>&apos;%1&apos; è %2: %3</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Outline: %1, approximate (not to scale of a drawing): %2</source>
        <translation>Sagoma: %1, approssimata (non in scala da un disegno): %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No outline drawn: %1</source>
        <translation>Nessuna sagoma disegnata: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+163"/>
        <source>a_tw</source>
        <translation>a_tw</translation>
    </message>
    <message>
        <location line="-140"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>static twist axis</source>
        <translation>asse di torsione statico</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>bending axis (modal, %1 Hz)</source>
        <translation>asse flessionale (modale, %1 Hz)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torsion axis (modal, %1 Hz)</source>
        <translation>asse torsionale (modale, %1 Hz)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>bending axis (set-up)</source>
        <translation>asse flessionale (allestimento)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torsion axis (set-up)</source>
        <translation>asse torsionale (allestimento)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>dynamic twist axis, %1 Hz</source>
        <translation>asse di torsione dinamico, %1 Hz</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>k_lat</source>
        <translation>k_lat</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>lateral stiffness at the load point, F / x_lat (eq. 29)</source>
        <translation>rigidezza laterale nel punto di carico, F / x_lat (eq. 29)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>k_tw</source>
        <translation>k_tw</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>twist stiffness about the axis, k_lat a_tw² (eq. 30)</source>
        <translation>rigidezza di torsione attorno all&apos;asse, k_lat a_tw² (eq. 30)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>twist arm: distance of the load point from the axis</source>
        <translation>braccio di torsione: distanza del punto di carico dall&apos;asse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>β</source>
        <translation>β</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inclination of the axis from the plate&apos;s v axis towards u</source>
        <translation>inclinazione dell&apos;asse dall&apos;asse v della piastra verso u</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>foot u</source>
        <translation>piede u</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>u of the axis&apos;s point nearest the load point</source>
        <translation>u del punto dell&apos;asse più vicino al punto di carico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>foot v</source>
        <translation>piede v</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>v of the axis&apos;s point nearest the load point</source>
        <translation>v del punto dell&apos;asse più vicino al punto di carico</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Dynamic, %1 Hz</source>
        <translation>Dinamica, %1 Hz</translation>
    </message>
</context>
<context>
    <name>mozzi::views::TwistCsvImport</name>
    <message>
        <location filename="../views/scene/twist_csv_import.cpp" line="+98"/>
        <source>Open a twist CSV</source>
        <translation>Apri un CSV di svergolamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>File CSV (*.csv *.txt);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Plate CSV files</source>
        <translation>File CSV della piastra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open CSV…</source>
        <translation>Apri CSV…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read a plate CSV as mozzi-cli twist static, dynamic or modal reads it</source>
        <translation>Legge un CSV della piastra come lo leggono mozzi-cli twist static, dynamic o modal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as</source>
        <translation>come</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep imported tests in the project</source>
        <translation>Conserva nel progetto le prove importate</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Store the imported static and dynamic tests shown as rig tests of the specimen (a new specimen when none is chosen)</source>
        <translation>Memorizza le prove statiche e dinamiche importate mostrate come prove al banco del provino (un nuovo provino se non ne è scelto alcuno)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>kind from the columns</source>
        <translation>tipo dalle colonne</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>static (force, displacements)</source>
        <translation>statico (forza, spostamenti)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dynamic (amplitude, phase)</source>
        <translation>dinamico (ampiezza, fase)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>modal (FRF Re, Im)</source>
        <translation>modale (FRF Re, Im)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modal FRFs are</source>
        <translation>Le FRF modali sono</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>receptance</source>
        <translation>recettanza</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>mobility</source>
        <translation>mobilità</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>accelerance</source>
        <translation>acceleranza</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bending mode</source>
        <translation>Modo flessionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torsion mode</source>
        <translation>Modo torsionale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency of the bending mode: the modal twist axis there is drawn (§1.4, §1.7)</source>
        <translation>Frequenza del modo flessionale: vi si disegna l&apos;asse di svergolamento modale (§1.4, §1.7)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frequency of the torsion mode: the modal twist axis there is drawn (§1.4, §1.7)</source>
        <translation>Frequenza del modo torsionale: vi si disegna l&apos;asse di svergolamento modale (§1.4, §1.7)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Cannot import %1: %2</source>
        <translation>Impossibile importare %1: %2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Some frequencies of %1 give no axis: %2</source>
        <translation>Alcune frequenze di %1 non danno un asse: %2</translation>
    </message>
    <message>
        <location line="+46"/>
        <location line="+18"/>
        <source>bending</source>
        <translation>flessionale</translation>
    </message>
    <message>
        <location line="-17"/>
        <location line="+18"/>
        <source>torsion</source>
        <translation>torsionale</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>no %1 axis at %2 Hz: %3</source>
        <translation>nessun asse %1 a %2 Hz: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Modal FRFs: %1</source>
        <translation>FRF modali: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 at %2 Hz (%3): β %4 ± %5°, foot (%6, %7) m</source>
        <translation>%1 a %2 Hz (%3): β %4 ± %5°, piede (%6, %7) m</translation>
    </message>
</context>
<context>
    <name>mozzi::views::WheelchairPage</name>
    <message>
        <location filename="../views/wheelchair/wheelchair_page.cpp" line="+177"/>
        <source>Correct the marked values first.</source>
        <translation>Correggere prima i valori segnalati.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Simulating the manoeuvre...</source>
        <translation>Simulazione della manovra...</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Wheelchair manoeuvre</source>
        <translation>Manovra della carrozzina</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+4"/>
        <location line="+3"/>
        <source>Not kept: %1</source>
        <translation>Non conservato: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kept in the project as analysis %1.</source>
        <translation>Conservato nel progetto come analisi %1.</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Cannot simulate: %1</source>
        <translation>Impossibile simulare: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>chair</source>
        <translation>carrozzina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C_α × %1</source>
        <translation>C_α × %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C_M × %1</source>
        <translation>C_M × %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: lateral amplitude %2 m, rear slip amplitude right %3°, left %4°</source>
        <translation>%1: ampiezza laterale %2 m, ampiezza della deriva posteriore destra %3°, sinistra %4°</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: radius %2 m at the end, rear slip right %3°, left %4°</source>
        <translation>%1: raggio %2 m alla fine, deriva posteriore destra %3°, sinistra %4°</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Simulate</source>
        <translation>Simula</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kept results:</source>
        <translation>Risultati conservati:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manoeuvres the project keeps (this page, mozzi-cli wheelchair slalom --project)</source>
        <translation>Manovre conservate nel progetto (questa pagina, mozzi-cli wheelchair slalom --project)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show</source>
        <translation>Mostra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trajectory of the centre of mass (thesis Figures 57 to 60)</source>
        <translation>Traiettoria del baricentro (Figure da 57 a 60 della tesi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>x [m]</source>
        <translation>x [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>y [m]</source>
        <translation>y [m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Right rear wheel slip angle</source>
        <translation>Angolo di deriva della ruota posteriore destra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Left rear wheel slip angle</source>
        <translation>Angolo di deriva della ruota posteriore sinistra</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>α [deg]</source>
        <translation>α [gradi]</translation>
    </message>
</context>
</TS>
